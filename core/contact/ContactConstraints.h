#pragma once
// The contact constraint rows of every pair (paper eq. (1), rows C_j): for each contact point, tied pairs
// give one row per component, u_s − Σ N_k u_k = 0; frictionless pairs one normal row while active,
// n·(u_s − Σ N_k u_k) = −g. The active set of frictionless pairs is updated from the solution.
#include <string>
#include <vector>

#include "contact/ContactSearch.h"
#include "model/Model.h"

namespace rollsim {

/// One term coef · u(body, node, comp) of a constraint row.
struct ConstraintTerm {
  int body, node, comp;
  double coef;
};

/// ConstraintRow::comp of a sticking point's one tangential row along n × e, where the supports hold its motion along
/// the axis e on both sides (analysis/ConstraintAssembly hold_supported_tangents).
constexpr int kSupportedTangent = 2;

struct ConstraintRow {
  std::vector<ConstraintTerm> terms;
  double rhs = 0;
  int pair = 0, point = 0, comp = -1;  // origin: contact pair, point, component (−1: normal row)
  Eigen::Vector3d dir{0, 0, 0};        // the direction the row constrains: the force on the slave is −λ dir
};

/// The contact points of one pair and which of them are active (tied: all); for sticking and Coulomb pairs, per
/// point: the relative position x_s − Σ N x_m it sticks at, whether it slips (Coulomb), the unit direction of the
/// friction force on the slave node while it slips, and its normal force −λ_n of the last solve [force].
struct PairState {
  std::vector<ContactPoint> points;
  std::vector<char> active;
  std::vector<Eigen::Vector3d> anchor;
  std::vector<char> slip;
  std::vector<Eigen::Vector3d> friction_dir;
  std::vector<double> normal_force;
  std::vector<int> switches;  // stick ↔ slip changes in the current step (a point that came back to slip stays)
  std::vector<int> contact_switches;  // in ↔ out changes in the current step (a point that came back in stays)
  std::vector<double> slid;           // tangential sliding accumulated over the converged steps [length]
  // |δ d₀ − v_t| of the trial slip that set friction_dir at this iterate (contact/Friction.h); 0 when the direction
  // came from elsewhere (the force at the return onto the cone, or the last step): the direction's stiffness needs it
  std::vector<double> trial_slip;
  // the friction direction where the step began (a point slipping then), or where the point began to slip in this
  // step; zero for a point that sticks: the memory of the trial force (contact/Friction.h)
  std::vector<Eigen::Vector3d> start_direction;
  double master_turn = 0;  // the turn of the master surface's material over the current step [radian]
};

/// True for the kinds with tangential rows while they stick (sticking, coulomb).
inline bool frictional(ContactKind k) { return k == ContactKind::Sticking || k == ContactKind::Coulomb; }

/// x_s − Σ N_k x_k of a point in the displaced configuration (u: every dof of every body, node-major).
Eigen::Vector3d relative_position(const ContactPair& p, const ContactPoint& c, const std::vector<Eigen::VectorXd>& u,
                                  int dim);

/// The displacement over the current step of the master's material under point c, when the pair's master surface
/// turns (ContactPair::master_turns; zero otherwise): (R(θ) − I)(x_s − centre), x_s the slave node in the
/// configuration u (where the step begins: on the master's surface where it touches) and θ the step's turn
/// (PairState::master_turn).
Eigen::Vector3d surface_travel(const Model& model, const ContactPair& p, const PairState& s, const ContactPoint& c,
                               const std::vector<Eigen::VectorXd>& u);

/// A step of load-factor span `span` begins at u: each pair whose master surface turns takes the step's share of its
/// turn, and its sticking points are anchored where the material under them goes over the step — they move with the
/// material, not with the master's mesh, which stays (an Eulerian roll). Call after the step's search.
void turn_master_surfaces(const Model& model, const std::vector<Eigen::VectorXd>& u, double span,
                          std::vector<PairState>& pairs);

/// Contact search of every pair of the model; unilateral points start active (and sticking) where the gap is
/// closed (gap ≤ 1e-9 of the search distance). Throws std::runtime_error naming a pair whose surfaces never meet.
std::vector<PairState> search_contacts(const Model& model);

/// Large sliding: the pairs that slide `when` (ContactPair::sliding) searched again in the configuration u (every
/// dof of every body, node-major), so that a slave node travels from master facet to master facet. A slave node keeps
/// its active flag and friction state; a node new to the pair is active where it touches or penetrates. A point that
/// sticks keeps its master point, its normal and tangents turned with the master facet — as it is in u, or in
/// `frames_at` when given (where the step is expected to end: analysis.contact_frames) —, unless the master surface
/// turns under a mesh that stays (ContactPair::master_turns): it is projected anew then, its anchor the same place
/// on the master.
void follow_contacts(const Model& model, const std::vector<Eigen::VectorXd>& u, std::vector<PairState>& pairs,
                     ContactPair::Sliding when, const std::vector<Eigen::VectorXd>* frames_at = nullptr);

/// The pairs whose slave body is `body` found again after that body's reference moved under its material (an ALE
/// step: its nodes put back, u its displacement from there — zero — and the other bodies' as they are): every point's
/// projection and reference separation anew, its status kept (active, stick or slip, its forces: the multipliers of
/// its rows stay theirs) unless it was put off the master — inactive then, as its row would pull it back onto the
/// master and add the gap's material —, a sticking point anchored where it is now; a node new to the pair is active
/// where it touches, one that left the search distance is dropped.
void refind_contacts(const Model& model, const std::vector<Eigen::VectorXd>& u, int body,
                     std::vector<PairState>& pairs);

/// How many active points of the pairs that slide per step would move if searched again in the configuration u:
/// their new projection is off by more than 1e-8 of the search distance along the normal, or off the master surface.
/// A step that converged on its first projections is not done while this is not zero.
int projections_moved(const Model& model, const std::vector<Eigen::VectorXd>& u, const std::vector<PairState>& pairs);

/// The same count with the largest offset of a moved point and that pair's limit (1e-8 of its search distance), for
/// a message: a point off the master surface counts as moved with no offset.
struct ProjectionDrift {
  int moved = 0;
  double largest = 0;  // the largest |gap| of a moved point at its new projection [length]
  double limit = 0;    // the limit that point exceeded [length]
};
ProjectionDrift projection_drift(const Model& model, const std::vector<Eigen::VectorXd>& u,
                                 const std::vector<PairState>& pairs);

/// The rows of the active points, pair by pair, point by point.
std::vector<ConstraintRow> contact_rows(const Model& model, const std::vector<PairState>& pairs);

/// Active-set update of the unilateral pairs from the displacements (node-major per body) and the multiplier
/// of each row (a point that enters sticks where it is): a point leaves when its multiplier is tensile beyond
/// `tolerance` × the largest |λ| of the rows (the relative accuracy of λ: round-off for a direct solve, the CG
/// tolerance for an iterative one — a λ that is zero to that accuracy keeps its point), enters when it penetrates
/// (beyond round-off; a turning master's true surface, where a window's placement and the contact agree to 1e-4 of
/// the search distance, by more than that: a column at the end of a 3D window's arc, stuck and tensile, left and
/// came back at every step, penetrating by 1 µm). A point that chatters (out, then in again within the step) stays in
/// for the rest of the step, tensile or not: the exact answer lies between the two statuses (a node at the edge of the
/// arc) and Newton would cycle. Returns the number of points that changed status.
int update_active_set(const Model& model, const std::vector<ConstraintRow>& rows, const Eigen::VectorXd& lambda,
                      const std::vector<Eigen::VectorXd>& displacement, std::vector<PairState>& pairs,
                      double tolerance = 0.0);

}  // namespace rollsim
