#include "solve/UpdatePolicy.h"

#include <cstdlib>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace rollsim {

std::vector<size_t> AlwaysUpdate::select(const BlockSystem& sys, const std::vector<double>& /*group_residuals*/) const {
  std::vector<size_t> all(sys.groups.size());
  std::iota(all.begin(), all.end(), size_t{0});
  return all;
}

std::string SelectiveUpdate::name() const {
  std::ostringstream s;
  s << "selective:" << tolerance_;
  return s.str();
}

std::vector<size_t> SelectiveUpdate::select(const BlockSystem& sys, const std::vector<double>& group_residuals) const {
  if (group_residuals.size() != sys.groups.size()) return AlwaysUpdate().select(sys, group_residuals);
  std::vector<size_t> chosen;
  for (size_t g = 0; g < sys.groups.size(); ++g)
    if (!(group_residuals[g] <= tolerance_)) chosen.push_back(g);  // NaN: refactor
  return chosen;
}

std::unique_ptr<UpdatePolicy> make_update_policy(const std::string& name) {
  if (name == "always") return std::make_unique<AlwaysUpdate>();
  if (name == "selective") return std::make_unique<SelectiveUpdate>(kSelectiveTolerance);
  const std::string prefix = "selective:";
  if (name.rfind(prefix, 0) == 0) {
    const std::string tol = name.substr(prefix.size());
    char* end = nullptr;
    const double t = std::strtod(tol.c_str(), &end);
    if (!tol.empty() && end == tol.c_str() + tol.size() && t > 0.0 && t < 1.0)
      return std::make_unique<SelectiveUpdate>(t);
    throw std::invalid_argument("update policy '" + name +
                                "': the tolerance after 'selective:' must be a number in "
                                "(0, 1), e.g. selective:0.01");
  }
  throw std::invalid_argument("unknown update policy '" + name + "' (valid: always, selective, selective:TOL)");
}

void mark_updated(BlockSystem& sys, const std::vector<size_t>& groups) {
  for (size_t g : groups) ++sys.groups.at(g).version;
}

}  // namespace rollsim
