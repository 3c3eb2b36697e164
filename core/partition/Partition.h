#pragma once
// A partition of one body's elements into subdomains — paper §2: "tear each body into subdomains",
// glued back by signed Boolean constraints (FETI, Farhat–Roux 1991).
#include <stdexcept>
#include <string>
#include <vector>

#include "model/BodyPartition.h"

namespace rollsim {

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
