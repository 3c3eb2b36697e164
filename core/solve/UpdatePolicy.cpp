#include "solve/UpdatePolicy.h"

#include <numeric>
#include <stdexcept>

namespace rollsim {

std::vector<size_t> AlwaysUpdate::select(const BlockSystem& sys, const std::vector<double>& /*group_residuals*/) const {
  std::vector<size_t> all(sys.groups.size());
  std::iota(all.begin(), all.end(), size_t{0});
  return all;
}

std::unique_ptr<UpdatePolicy> make_update_policy(const std::string& name) {
  if (name == "always") return std::make_unique<AlwaysUpdate>();
  throw std::invalid_argument("unknown update policy '" + name + "' (valid: always)");
}

void mark_updated(BlockSystem& sys, const std::vector<size_t>& groups) {
  for (size_t g : groups) ++sys.groups.at(g).version;
}

}  // namespace rollsim
