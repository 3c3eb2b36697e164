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
// Node-to-face in 3D on a bilinear face (Wriggers, §9, node-to-surface; the same choices): slave at (ξ, η),
// a_α = x_,α, normal n = a_1 × a_2 / |a_1 × a_2|, metric m_αβ = a_α · a_β, curvature h_αβ = n · x_,αβ (bilinear:
// only h_12 = n · x_,ξη, the face's warp), δr̃ = δx_s − Σ N_k δx_k and δã_α = Σ N_k,α δx_k (ξ held), gap
// g = n · (x_s − x(ξ, η)),
//   sliding normal row: λ ∂²g/∂u² = λ [−δξ^α n·Δã_α − n·δã_α Δξ^α − h_αβ δξ^α Δξ^β
//                                       + g m^αβ (n·δã_α + h_αγ δξ^γ)(n·Δã_β + h_βδ Δξ^δ)],
//   (m_αβ − g h_αβ) δξ^β = a_α · δr̃ + g n · δã_α — exact and symmetric;
//   ξ held: normal row λ Δn · δr̃ with Δn = −a^α (n · Δã_α) (a^α = m^αβ a_β); tangential rows (t_1 = a_1/|a_1|,
//   t_2 = n × t_1) λ Δt_k · δr̃ with Δt_1 = (I − t_1 t_1ᵀ) Δã_1 / |a_1|, Δt_2 = Δn × t_1 + n × Δt_1 — unsymmetric;
//   the symmetric part is given. A projection clamped to the face's border (|ξ| or |η| = 1) counts as held.
// In 2D and on a flat face (h = 0) every term has a master factor (N0, n·δã_α): the slave–slave part is zero, and a
// rigid master (no free dof) gets nothing; on a warped face the normal turns as the slave slides over it, and the
// terms in h give a slave–slave part too (into the slave's block). Rows that do not follow the configuration (small
// sliding, and `large`, whose rows stay fixed through a step's iterations) have a constant C: no term.
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
