#pragma once
// A partition of one body's elements into subdomains — paper §2: "tear each body into subdomains",
// glued back by signed Boolean constraints (FETI, Farhat–Roux 1991).
#include <stdexcept>
#include <string>
#include <vector>

namespace rollsim {

/// element -> subdomain id in [0, num_subdomains).
struct Partition {
  int num_subdomains = 1;
  std::vector<int> element_subdomain;
  std::string description;  // how it was made: "4x4", "metis:16", "explicit" (messages, summaries)
};

/// One problem of a partition, with the path of the offending entry (maps 1:1 onto the project's Issue).
struct PartitionProblem {
  std::string path;
  std::string message;
};

/// An invalid partition or partition request; what() lists every problem as "path: message".
class PartitionError : public std::runtime_error {
 public:
  explicit PartitionError(std::vector<PartitionProblem> problems);
  const std::vector<PartitionProblem>& problems() const { return problems_; }

 private:
  std::vector<PartitionProblem> problems_;
};

/// The elements of every subdomain, ascending. Ids outside [0, num_subdomains) are skipped.
std::vector<std::vector<int>> subdomain_elements(const Partition& p);

}  // namespace rollsim
