#pragma once
// One group's part of the interface operator formed explicitly, F_g = C_g K_g⁺ C_eq,gᵀ, for the `dense` interface
// solver. Its constraints touch only the group's contact and glue dofs D (a few hundred on a rolling pass, against
// ~10⁴ dofs), so F_g = C_g(:, D) Φ C_eq,g(:, D)ᵀ with the flexibility Φ = K⁺(D, D): one solve per touched dof, all
// of them together as one block (level-3 work). Φ is kept while the group's factor is (Group::version), so a group
// the selective update keeps solves only for the dofs that newly enter its constraints (a roll whose contact arc
// moves on): its part of F then costs next to nothing.
#include <vector>

#include "solve/GroupSolver.h"

namespace rollsim {

class InterfaceFlexibility {
 public:
  /// F_g (multipliers × multipliers, dense) for the group's current C and C_eq and its factor in `solver`.
  Eigen::MatrixXd interface_block(const Group& g, GroupSolver& solver);
  /// Columns of K⁺ solved for so far (a measure of the work: each is one forward and back substitution's worth)
  long columns_solved() const { return solved_; }

 private:
  /// Solves for the dofs of `dofs` that Φ does not hold yet, and appends them to Φ.
  void extend(const std::vector<int>& dofs, GroupSolver& solver);
  /// C's columns renumbered to Φ's rows (every column of C must be held)
  SparseMatrix on_held_dofs(const SparseMatrix& C) const;

  long version_ = -1;          // the group version Φ was solved with (−1: none)
  std::vector<int> dofs_;      // the dofs Φ holds, in the order of its rows
  std::vector<int> position_;  // position_[dof]: its row in Φ, −1 when not held
  Eigen::MatrixXd phi_;
  long solved_ = 0;
};

}  // namespace rollsim
