#include "partition/Partition.h"

namespace rollsim {

namespace {
std::string join(const std::vector<PartitionProblem>& problems) {
  std::string text;
  for (const PartitionProblem& p : problems) text += (text.empty() ? "" : "\n") + p.path + ": " + p.message;
  return text;
}
}  // namespace

PartitionError::PartitionError(std::vector<PartitionProblem> problems)
    : std::runtime_error(join(problems)), problems_(std::move(problems)) {}

std::vector<std::vector<int>> subdomain_elements(const Partition& p) {
  std::vector<std::vector<int>> elements(static_cast<size_t>(std::max(0, p.num_subdomains)));
  for (size_t e = 0; e < p.element_subdomain.size(); ++e) {
    const int s = p.element_subdomain[e];
    if (s >= 0 && s < p.num_subdomains) elements[static_cast<size_t>(s)].push_back(static_cast<int>(e));
  }
  return elements;
}

}  // namespace rollsim
