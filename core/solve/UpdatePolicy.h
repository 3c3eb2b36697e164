#pragma once
// Which groups an iteration re-assembles and refactors (paper §1, "selective Newton update"). The analysis asks the
// policy before each Newton iteration (the linear analysis: once, after assembling), re-assembles the groups it
// selects and bumps their Group::version; every strategy refactors exactly the groups whose version changed (the
// global strategies, `direct` and `skyline`, refactor their one matrix when any did or the constraint rows changed).
#include <memory>
#include <string>
#include <vector>

#include "solve/BlockSystem.h"

namespace rollsim {

class UpdatePolicy {
 public:
  virtual ~UpdatePolicy() = default;
  virtual std::string name() const = 0;
  /// The groups to re-assemble and refactor, ascending, from each group's relative residual ‖r_g‖ / ‖r_g,0‖ (empty:
  /// not known yet, e.g. before the first iteration of an increment).
  virtual std::vector<size_t> select(const BlockSystem& sys, const std::vector<double>& group_residuals) const = 0;
  /// False when select() ignores the residuals (the driver then need not compute them before assembling).
  virtual bool uses_residuals() const { return true; }
  /// The residual share ‖r_g‖ / ‖r‖ above which select() picks a group (0: every group).
  virtual double threshold() const { return 0.0; }
};

/// The policy a run asks for (solver.update, --update): its kind and, selective, its tolerance. The default member
/// values are the one default of the option.
struct UpdateSetting {
  enum class Kind { Always, Selective };
  Kind kind = Kind::Always;
  double tolerance = 0.01;  // selective: the paper's examples
};

/// The words of the kinds, in enum order (`always`, `selective`; a selective tolerance follows as ":TOL").
const std::vector<std::string>& update_policy_names();
/// `always`, `selective` or `selective:TOL` (0 < TOL < 1); anything else throws std::invalid_argument naming the
/// valid ones.
UpdateSetting parse_update(const std::string& text);
/// As the run reports it: `always`, `selective:0.01`.
std::string to_string(const UpdateSetting& setting);

/// Mixed I / DD-I: every group, every iteration.
class AlwaysUpdate final : public UpdatePolicy {
 public:
  std::string name() const override { return update_policy_names()[0]; }
  std::vector<size_t> select(const BlockSystem& sys, const std::vector<double>& group_residuals) const override;
  bool uses_residuals() const override { return false; }
};

/// Mixed II / DD-II (paper §1): a group keeps its stiffness and factor while its residual norm is at most
/// `tolerance` × the total residual norm (‖r_g‖ ≤ tol ‖r‖); the others are re-assembled and refactored. Without
/// residuals (none known yet) every group is selected.
class SelectiveUpdate final : public UpdatePolicy {
 public:
  explicit SelectiveUpdate(double tolerance) : tolerance_(tolerance) {}
  std::string name() const override;
  std::vector<size_t> select(const BlockSystem& sys, const std::vector<double>& group_residuals) const override;
  double tolerance() const { return tolerance_; }
  double threshold() const override { return tolerance_; }

 private:
  double tolerance_;
};

std::unique_ptr<UpdatePolicy> make_update_policy(const UpdateSetting& setting);
/// make_update_policy(parse_update(text)).
std::unique_ptr<UpdatePolicy> make_update_policy(const std::string& text);

/// Bumps the version of each group in `groups` (their K was just re-assembled): what the strategies refactor.
void mark_updated(BlockSystem& sys, const std::vector<size_t>& groups);

}  // namespace rollsim
