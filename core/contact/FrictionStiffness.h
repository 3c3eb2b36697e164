#pragma once
// The stiffness of the friction direction's turn (3D). A slipping point carries the friction force F d on its slave
// node and −N_k F d on its master nodes (F = μ N, or the shear cap), d = (δ d₀ − v_t) / |δ d₀ − v_t| its trial force's
// direction, v_t the tangential part of its relative motion over the step (contact/Friction.h). In 2D d = ±t cannot
// turn in the plane; in 3D it turns with v_t. With R̃ δu = δu_s − Σ N_k δu_k (the projection held) and
// P = I − d dᵀ − n nᵀ = w wᵀ, w = n × d:
//   ∂d/∂u = −P R̃ / |δ d₀ − v_t|  (the derivative of a unit vector),
// and the friction loads are r's, so the tangent −∂r/∂u gains
//   K_d = (F / |δ d₀ − v_t|) R̃ᵀ w wᵀ R̃   — symmetric, positive semidefinite, rank one per point.
// Left out (second order): the projection's motion (∂N_k, the master's motion over the step weighted by it) and the
// normal's turn with the master facet. A point whose direction was not set from its slip at this iterate
// (PairState::trial_slip 0: just returned onto the cone, the first iteration of a step) gets no term: its residual's
// direction does not move with u there.
#include <vector>

#include "contact/ContactStiffness.h"

namespace rollsim {

/// K_d of every slipping point of the pairs that can slip (3D; empty in 2D), over the point's slave and master nodes
/// in body terms: the slave–slave part belongs in the slave's block, the master–master part in the master's, the
/// slave–master part joins two bodies (the entries say which). Every entry (i, j) has its (j, i).
std::vector<StiffnessEntry> slip_direction_stiffness(const Model& model, const std::vector<PairState>& pairs);

/// The same K_d as one row per slipping point and its stiffness k = F / |δ d₀ − v_t|: K_d = Σ k cᵀc with c the row's
/// coefficients wᵀR̃ (rows[i].dir = w). A solver that cannot join two groups' stiffness takes K_d this way, as rows
/// c δu − μ_i / k_i = 0 with a multiplier μ_i of their own (a compliant constraint: BlockSystem::compliance), which
/// holds the slave–master part that its groups' blocks cannot.
struct SlipDirectionRows {
  std::vector<ConstraintRow> rows;
  std::vector<double> stiffness;
};
SlipDirectionRows slip_direction_rows(const Model& model, const std::vector<PairState>& pairs);

}  // namespace rollsim
