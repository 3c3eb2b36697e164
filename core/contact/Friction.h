#pragma once
// Coulomb friction inside the Newton loop, with no inner contact loop: a sticking point holds its relative position
// through tangential rows; after each solve, a point whose tangential force exceeds μ times its normal force slips
// (its tangential rows go, and a friction force of exactly μ times the normal force of the last solve acts on both
// bodies as a load), and a slipping point whose trial force falls inside the cone sticks again.
//
// The friction force of a slipping point points along its trial force: the return map of Coulomb's law with an elastic
// slip δ (elastoplastic friction as in Wriggers's Computational Contact Mechanics; Abaqus's slip tolerance), d = (δ d₀
// − v_t) / |δ d₀ − v_t|, with v_t its slip over the step and d₀ its direction where the step began (or where it began
// to slip in this step) — Coulomb's −v_t/|v_t| once the slip is large against δ, and d₀ while it is small. δ =
// slip_tolerance × the point's facet size (√ of its tributary area in 3D, its tributary length in 2D). A direction
// taken from the slip alone turned over at every iteration where a point slips next to nothing, and threw it to and fro
// with growing slips (the 3D rolling pass with Coulomb friction diverged in its first millimetre;
// docs/BENCHMARKS-ROLLING.md); the trial force's turns are bounded by δ, and so is its stiffness F / |δ d₀ − v_t|
// (contact/FrictionStiffness). The bodies' stiffness blocks stay symmetric. A strategy that solves unsymmetric systems
// gets the friction force's dependence on the normal multiplier in the multipliers' columns (slip_coupling); for the
// others the friction force lags one iteration behind the normal force, and Newton's residual carries the difference.
#include <vector>

#include "contact/ContactConstraints.h"

namespace rollsim {

/// Stick/slip update of the frictional pairs from the rows and multipliers of the last solve, the displacements
/// now (u) and at the start of the step (u_start; every dof of every body, node-major). Records every active
/// point's normal force, and a slipping point's trial slip |δ d₀ − v_t| beside the direction it sets
/// (PairState::trial_slip); returns the number of points that changed between stick and slip. A point that went back
/// from slip to stick once in the step and slips again stays slipping for the rest of the step (no chatter). A pair
/// that holds its slave body (ContactPair::holds_slave) keeps the least overloaded of the points that would start to
/// slip sticking when no other point sticks: with every point slipping nothing would hold the body (a rolling slab
/// whose friction cannot draw it in: its tangential force then stays above the limit).
int update_friction(const Model& model, const std::vector<ConstraintRow>& rows, const Eigen::VectorXd& lambda,
                    const std::vector<Eigen::VectorXd>& u, const std::vector<Eigen::VectorXd>& u_start,
                    std::vector<PairState>& pairs);

/// The elastic slip δ of point c of pair p (slip_tolerance × its facet size) [length].
double elastic_slip(const ContactPair& p, const ContactPoint& c, int dim);

/// A step begins: every point may switch between stick and slip, in and out again (the chatter rules of
/// update_friction and update_active_set); a slipping point's direction is the last step's (no trial_slip), and the
/// memory d₀ of its trial force.
void new_step(std::vector<PairState>& pairs);

/// A step converged: every active point of a unilateral pair adds the tangential part of its relative motion over
/// the step (u_start → u) to the distance it slid.
void accumulate_slip(const Model& model, const std::vector<Eigen::VectorXd>& u,
                     const std::vector<Eigen::VectorXd>& u_start, std::vector<PairState>& pairs);

/// Whether a pair's points can slip: Coulomb, or a sticking pair with a friction stress cap (shear_limit).
bool can_slip(const ContactPair& p);

/// The largest tangential force a point of pair p carries: μ × normal_force (Coulomb), capped at shear_limit × its
/// tributary measure `weight`.
double slip_force(const ContactPair& p, double normal_force, double weight);

/// The unit direction of the friction force on the slave node of slipping point j: its friction direction in the
/// tangent plane of its master facet (zero when it has none).
Eigen::Vector3d friction_direction(const PairState& s, size_t j);

/// Whether slipping point j of pair p carries μ × its normal force (Coulomb, under the shear cap, with a friction
/// direction): its friction force then moves with its normal multiplier λ_n (−μ λ_n along the direction).
bool slip_moves_with_normal(const ContactPair& p, const PairState& s, size_t j);

/// Which slipping points friction_loads counts: all, or those whose friction force does not move with λ_n (the
/// capped ones) — when the others are in the system's matrix through slip_coupling.
enum class FrictionLoads { All, Capped };

/// The friction forces of the slipping points, per body, every dof (node-major): μ N along the friction
/// direction on the slave node, the opposite on the master nodes by their weights. Empty when no pair can slip.
std::vector<Eigen::VectorXd> friction_loads(const Model& model, const std::vector<PairState>& pairs,
                                            FrictionLoads which = FrictionLoads::All);

/// The consistent linearisation of slipping Coulomb friction: for each row of `rows`, the terms μ d (slave node) and
/// −μ N_k d (master nodes) when it is the normal row of a point whose friction force moves with its multiplier
/// (slip_moves_with_normal; d its friction direction), no terms otherwise. The row's multiplier then enters the
/// equations through C + these terms (Group::C_eq): the friction force μ N = −μ λ_n is solved for with λ_n instead
/// of lagging one iteration behind it, and Newton converges quadratically on a fixed stick/slip set.
std::vector<ConstraintRow> slip_coupling(const Model& model, const std::vector<PairState>& pairs,
                                         const std::vector<ConstraintRow>& rows);

}  // namespace rollsim
