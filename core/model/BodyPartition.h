#pragma once
// A body's partition into subdomains as plain data (element -> subdomain); partition/ makes and checks it.
#include <string>
#include <vector>

namespace rollsim {

/// element -> subdomain id in [0, num_subdomains).
struct Partition {
  int num_subdomains = 1;
  std::vector<int> element_subdomain;
  std::string description;  // how it was made: "4x4", "metis:16", "explicit" (messages, summaries)
};

}  // namespace rollsim
