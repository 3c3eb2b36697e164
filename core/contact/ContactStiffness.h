#pragma once
// The contact's geometric stiffness: how the multipliers' forces Cᵀλ turn with the configuration when the rows C
// follow it (pairs searched at every Newton iteration, ContactPair::Sliding::Iteration). Node-to-segment in 2D
// (Wriggers, Computational Contact Mechanics, 2nd ed., §9.1): for a segment a → b of length l, unit tangent t and
// normal n, a slave node at ξ with r = x_s − (1 − ξ) a − ξ b and g = n · r,
//   sliding normal row (ξ moves with the slave):  λ ∂²g/∂u² = −λ/l (D N0ᵀ + N0 Dᵀ) − λ g/l² N0 N0ᵀ,
//   D = [t; −(1 − ξ) t; −ξ t], N0 = [0; −n; n] over (slave, a, b) — exact and symmetric, since C = ∂g/∂u there;
//   a row whose ξ is held (a sticking point's normal and tangential rows, a projection clamped to a vertex):
//   λ ∂C/∂u = −λ/l D N0ᵀ (normal row) or λ/l Dₙ N0ᵀ (tangential row, Dₙ = [n; −(1 − ξ) n; −ξ n]) — unsymmetric;
//   its symmetric part is given (an approximation).
// Every term has a master factor (N0): the slave–slave part is zero, and a rigid master (no free dof) gets nothing.
// Rows that do not follow the configuration (small sliding, and `large`, whose rows stay fixed through a step's
// iterations) have a constant C: no term. 3D (node-to-face) is not linearised: no term.
#include <Eigen/Dense>
#include <vector>

#include "contact/ContactConstraints.h"

namespace rollsim {

/// One entry of the geometric stiffness, row dof (body_i, node_i, comp_i), column dof (body_j, node_j, comp_j).
struct StiffnessEntry {
  int body_i, node_i, comp_i, body_j, node_j, comp_j;
  double value;
};

/// Σ_r λ_r ∂C_r/∂u over the kept rows (rows[kept[i]] carries lambda[i]) of the pairs that slide at every iteration,
/// at the configuration u (every dof of every body, node-major) the rows were found in. Symmetric: every entry (i, j)
/// has its (j, i).
std::vector<StiffnessEntry> contact_geometric_stiffness(const Model& model, const std::vector<PairState>& pairs,
                                                        const std::vector<ConstraintRow>& rows,
                                                        const std::vector<int>& kept, const Eigen::VectorXd& lambda,
                                                        const std::vector<Eigen::VectorXd>& u);

}  // namespace rollsim
