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

std::string SelectiveUpdate::name() const { return to_string({UpdateSetting::Kind::Selective, tolerance_}); }

std::vector<size_t> SelectiveUpdate::select(const BlockSystem& sys, const std::vector<double>& group_residuals) const {
  if (group_residuals.size() != sys.groups.size()) return AlwaysUpdate().select(sys, group_residuals);
  std::vector<size_t> chosen;
  for (size_t g = 0; g < sys.groups.size(); ++g)
    if (!(group_residuals[g] <= tolerance_)) chosen.push_back(g);  // NaN: refactor
  return chosen;
}

const std::vector<std::string>& update_policy_names() {
  static const std::vector<std::string> names{"always", "selective"};
  return names;
}

UpdateSetting parse_update(const std::string& text) {
  const std::string& always = update_policy_names()[0];
  const std::string& selective = update_policy_names()[1];
  if (text == always) return {};
  UpdateSetting s;
  s.kind = UpdateSetting::Kind::Selective;
  if (text == selective) return s;
  const std::string prefix = selective + ":";
  if (text.rfind(prefix, 0) != 0)
    throw std::invalid_argument("unknown update policy '" + text + "' (valid: " + always + ", " + selective + ", " +
                                prefix + "TOL)");
  const std::string tol = text.substr(prefix.size());
  char* end = nullptr;
  s.tolerance = std::strtod(tol.c_str(), &end);
  if (tol.empty() || end != tol.c_str() + tol.size() || !(s.tolerance > 0.0 && s.tolerance < 1.0))
    throw std::invalid_argument("update policy '" + text + "': the tolerance after '" + prefix +
                                "' must be a number in (0, 1), e.g. " + to_string(UpdateSetting{s.kind}));
  return s;
}

std::string to_string(const UpdateSetting& setting) {
  if (setting.kind == UpdateSetting::Kind::Always) return update_policy_names()[0];
  std::ostringstream s;
  s << update_policy_names()[1] << ":" << setting.tolerance;
  return s.str();
}

std::unique_ptr<UpdatePolicy> make_update_policy(const UpdateSetting& setting) {
  if (setting.kind == UpdateSetting::Kind::Always) return std::make_unique<AlwaysUpdate>();
  return std::make_unique<SelectiveUpdate>(setting.tolerance);
}

std::unique_ptr<UpdatePolicy> make_update_policy(const std::string& text) {
  return make_update_policy(parse_update(text));
}

void mark_updated(BlockSystem& sys, const std::vector<size_t>& groups) {
  for (size_t g : groups) ++sys.groups.at(g).version;
}

}  // namespace rollsim
