#pragma once
// FETI preconditioners of the interface operator F = Σ_g C_g K_g⁺ C_gᵀ (beyond the paper, which ran
// unpreconditioned): with W the multiplier scaling (1/multiplicity on subdomain glue rows; on a contact row 1 for
// the groups of its slave body and 0.1 for the other side's — ConstraintBlock::preconditioned_by),
//   lumped:    M⁻¹ = Σ_g W C_g K_g C_gᵀ W            (the group stiffness on its interface dofs)
//   dirichlet: M⁻¹ = Σ_g W C_g S_g C_gᵀ W,  S_g = K_bb − K_bi K_ii⁻¹ K_ib   (Schur complement on the interface)
// (Farhat, Mandel, Roux 1994; Rixen, Farhat 1999 for the scaling).
#include <memory>
#include <string>
#include <vector>

#include "solve/BlockSystem.h"
#include "solve/GroupDistribution.h"
#include "solve/SolverOptions.h"

namespace rollsim {

class InterfacePreconditioner {
 public:
  virtual ~InterfacePreconditioner() = default;
  /// Prepares for the groups' current stiffness (factors K_ii for dirichlet, by CholeskyOrLU: LU if indefinite).
  virtual void setup(const BlockSystem& sys) = 0;
  /// z = M⁻¹ w
  virtual Eigen::VectorXd apply(const BlockSystem& sys, const Eigen::VectorXd& w) const = 0;
  /// M⁻¹ X for a sparse block of columns (the rigid modes' G for the Q = M⁻¹ projector of ProjectedCG). Each group
  /// works only on the columns that touch its interface, so the cost follows the neighbours of each floating
  /// group, not (columns × groups); the result is as sparse as M⁻¹'s coupling allows.
  virtual SparseMatrix apply_columns(const BlockSystem& sys, const SparseMatrix& X) const = 0;
};

/// None gives nullptr. `threads`: the groups' blocks are set up and applied concurrently (summed in group order: the
/// result does not depend on it). `spread`: the groups over processes — each sets up and applies the blocks of the
/// groups it holds, apply() sums over the processes; apply_columns() is then refused (std::invalid_argument).
std::unique_ptr<InterfacePreconditioner> make_interface_preconditioner(
    Preconditioner kind, int threads = 1, std::shared_ptr<const GroupDistribution> spread = nullptr);

}  // namespace rollsim
