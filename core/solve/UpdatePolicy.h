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
};

/// Mixed I / DD-I: every group, every iteration.
class AlwaysUpdate final : public UpdatePolicy {
 public:
  std::string name() const override { return "always"; }
  std::vector<size_t> select(const BlockSystem& sys, const std::vector<double>& group_residuals) const override;
};

/// "always" (the nonlinear layer adds "selective"); anything else throws std::invalid_argument naming the valid ones.
std::unique_ptr<UpdatePolicy> make_update_policy(const std::string& name);

/// Bumps the version of each group in `groups` (their K was just re-assembled): what the strategies refactor.
void mark_updated(BlockSystem& sys, const std::vector<size_t>& groups);

}  // namespace rollsim
