#pragma once
// The interface problem of ProjectedCG.h / ProjectedGMRES.h solved directly, once F is formed (InterfaceFlexibility):
//   [ F   −G ] [λ]   [b]
//   [ G̃ᵀ   0 ] [α] = [e]
// (G̃ = G unless the problem is unsymmetric), by LU with partial pivoting and a step of iterative refinement. With a
// few hundred contact multipliers this is far cheaper than a Krylov method that needs nearly as many iterations as
// there are multipliers, each a forward and back substitution with every group's factor.
//
// Only independent constraint rows are solved for, as `direct` does (ConstraintBasis.h): stick rows of slave nodes on
// a symmetry plane, whose own dofs are prescribed, hold only the roll's dofs — four rows on three — and make F
// singular. Rows that are nearly dependent (the same rows with the slave's small tilt terms) stay: they are as much
// part of the problem as in `direct`'s bordered matrix, but F squares their near-dependence, so F can be far worse
// conditioned than that matrix (1e16 and more on the 3D pass) while λ's part that moves the bodies stays accurate.
#include <vector>

#include "solve/ProjectedCG.h"

namespace rollsim {

/// The solve counts as converged when ‖b + Gα − Fλ‖ / ‖b‖ and the constraint error are below this.
constexpr double kDenseInterfaceResidual = 1e-8;

/// `F`: multipliers × multipliers; `rows`: the independent constraint rows (λ is 0 on the others). The result has
/// iterations = 0, residuals {1, ‖b + Gα − Fλ‖ / ‖b‖} over the rows solved, and max_constraint_error as the Krylov
/// solvers report them; breakdown (λ not usable) when either is above kDenseInterfaceResidual or not finite.
ProjectedCGResult dense_interface_solve(const Eigen::MatrixXd& F, const InterfaceProblem& problem,
                                        const std::vector<int>& rows);

}  // namespace rollsim
