#include "analysis/NewtonStatic.h"

#include "analysis/IncrementOptions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include "analysis/AleStep.h"
#include "analysis/ConstraintAssembly.h"
#include "analysis/ContactResults.h"
#include "analysis/DriverSteps.h"
#include "analysis/ForcingSequence.h"
#include "analysis/GroupLayout.h"
#include "analysis/HeatConduction.h"
#include "analysis/LinearStatic.h"
#include "analysis/Recovery.h"
#include "base/Format.h"
#include "base/Stopwatch.h"
#include "contact/ContactConstraints.h"
#include "contact/ContactStiffness.h"
#include "contact/Friction.h"
#include "contact/FrictionStiffness.h"
#include "mesh/ElementQuality.h"
#include "solve/Factorization.h"

namespace rollsim {

namespace {

/// How one attempt at a step ended: converged, cancelled, or failed with a cause (then cut back and retried).
struct Attempt {
  RunStatus status;
  std::string cause;  // why it failed (empty when converged or cancelled)
  int iterations = 0;
};

/// The multipliers' accuracy of an exact (direct or dense) solve: a looser one is an interface Krylov solve's.
constexpr double kExactInterface = 1e-10;
/// The share of the constraint check's limit an inexact interface solve need not go below (the rest is left to the
/// nonlinear change of the rows over the iteration).
constexpr double kEnoughConstraint = 0.1;

/// What one iterate measures against Newton's checks.
struct Iterate {
  bool balanced = false;        // the residual ratio is within analysis.tolerance
  double relative = 0;          // ‖r_k‖ / the step's residual scale
  int changed = 0;              // contact points whose status the last solve changed
  double correction = 0;        // ‖du‖ of the last solve
  double step = 0;              // ‖u − u_n‖, the step's displacement so far
  double constraint = 0;        // max |C u − d| over the contact and glue rows
  double constraint_limit = 0;  // analysis.tolerance × max(max |u − u_n|, BlockSystem::d_reference)
};

/// A tangent that fails to factor after the load took effect (the model was held then, so no advice on supports):
/// what the factorization found — at finite strain a part under heavy compression can lose stability alone.
std::string tangent_failure(const std::string& what) {
  return "the tangent is singular or not positive definite (" + what +
         "): under this load a part of the model loses its stiffness — plastic flow without hardening, or at finite "
         "strain a compressed body or FETI subdomain that cannot carry the load alone";
}

/// The run: the block system, the current iterate (u per group, λ, active set) and the last converged state.
class NewtonRun {
 public:
  NewtonRun(const Model& model, SolverStrategy& solver, const UpdatePolicy& policy, AnalysisObserver& obs,
            const NewtonOptions& opt, const IncrementMeasure* measure, const MeshMotion* motion)
      : own_(motion ? std::make_shared<Model>(model) : nullptr),
        model_(own_ ? *own_ : model),
        measure_(measure),
        motion_(motion),
        solver_(solver),
        policy_(policy),
        obs_(obs),
        opt_(opt),
        layout_(model_, solver.uses_subdomains(), multiplier_choice(solver.options())),
        forcing_(opt.forcing, solver.options().cg_tolerance, kInterfaceTolerancePerNewton * opt.tolerance) {
    for (const Group& g : layout_.system().groups) u_.push_back(Eigen::VectorXd::Zero(g.R.rows()));
    unfactored_.assign(u_.size(), 0);
    // petsc: every rank runs this driver alike, assembling the tangent of its own subdomain only
    layout_.assembler().set_local(solver.local_groups(all_groups(layout_.system())));
    layout_.assembler().set_threads(solver.options().threads);
    try {
      pairs_ = search_contacts(model);
    } catch (const std::runtime_error& e) {
      throw AnalysisError(e.what());
    }
    for (const ContactPair& p : model.contacts) {
      step_sliding_ = step_sliding_ || p.sliding == ContactPair::Sliding::Step;
      iteration_sliding_ = iteration_sliding_ || p.sliding == ContactPair::Sliding::Iteration;
      couple_slip_ = couple_slip_ || p.kind == ContactKind::Coulomb;
    }
    if (model.conducts_heat()) heat_ = std::make_unique<HeatConduction>(model);
    for (const Body& b : model.bodies)
      for (const auto& x : b.mesh.nodes)
        for (double c : x) position_scale_ = std::max(position_scale_, std::abs(c));
    if (motion_) refuse_ale();
    couple_slip_ = couple_slip_ && opt.friction_tangent == FrictionTangent::Consistent && solver.solves_unsymmetric();
    if (opt.contact_tangent == ContactTangent::Full && !solver.assembles_globally())
      throw AnalysisError(
          "analysis.contact_tangent 'full' joins the slave's and the master's stiffness, which only a solver with one "
          "global matrix (direct, skyline) can take: use 'groups' with this solver");
    save();
  }

  Results run();

 private:
  Attempt attempt(int increment, int attempt_no, double from, double lf);
  /// The contact rows at the current iterate; `step_begins`: the pairs that slide large per step are searched again
  /// (in the configuration the step starts from), those that slide per iteration always are.
  void set_constraints(double lf, bool step_begins = false);
  /// The last solve's λ carried to the rows `keys` (the same point's same component; 0 for a new row), the glue rows
  /// as they were: where the interface solve starts. Empty when λ belongs to no row set of this size.
  Eigen::VectorXd multiplier_guess(const std::vector<std::array<int, 3>>& keys, long rows) const;
  /// Residuals (and trial states) of `which`, tangents of `tangent`; empty cause when no element inverted.
  std::string assemble(const std::vector<size_t>& which, const std::vector<size_t>& tangent,
                       GroupAssembler::Factors at);
  /// The slipping points' friction forces (μ × the normal force of the last solve) added to the residuals of `which`
  /// (with couple_slip_: those whose force the system's C_eq holds are left to it).
  void add_friction(const std::vector<size_t>& which);
  /// True when the prescribed dofs of group g's body move over the step `at` predicts.
  bool prescribed_moves(size_t g, GroupAssembler::Factors at) const;
  /// The contact's geometric stiffness with the last solve's λ, at the current rows (nothing while λ does not belong
  /// to them), and the slipping points' friction direction stiffness, into the tangents of `tangent` (and, for
  /// `full`, the system's coupling).
  void add_contact_stiffness(double lf, const std::vector<size_t>& tangent);
  /// ‖R_g‖ = ‖f_g − C_gᵀλ‖ per group (λ of the last solve when it belongs to the current rows, else 0).
  std::vector<double> group_residuals() const;
  std::vector<Eigen::VectorXd> body_displacements(double lf) const;
  /// du · (r − Cᵀλ) over the groups (the residual's work along the step).
  double energy(const std::vector<Eigen::VectorXd>& du) const;
  /// One secant step on s(η) = du · (r(u_prev + η du) − Cᵀλ) when the full step leaves |s(1)| > |s(0)| / 2
  /// (Crisfield 1991, §9.3): moves the iterate back to u_prev + η du and re-assembles there.
  std::string line_search(const std::vector<size_t>& tangent, GroupAssembler::Factors at, double& eta);
  /// Stick/slip and active-set update from the last solve (its λ and the iterate); the number of points changed.
  int update_statuses(double lf);
  /// The first of Newton's checks the iterate fails — the residual ratio, the contact statuses, the constraint rows
  /// against the step's displacement, the correction ‖du‖ against it — with its value and limit; "" when it passes
  /// them (then the projections are checked: unmet_projections).
  std::string unmet_check(const Iterate& it) const;
  /// The iterate's residual ratio, step and constraint error (the rows set at it); `from`: u where the step began.
  Iterate measure(double residual, double first, int k, const std::vector<Eigen::VectorXd>& from) const;
  std::string unmet_projections(double relative, const ProjectionDrift& drift) const;
  /// For a check an inexact interface solve can fail: its tolerance named as a remedy ("" for an exact solve).
  std::string interface_hint() const;
  /// What a run that ran out of cut-backs on an inverted element can change, in the user's settings: smaller steps
  /// from the start (NewtonOptions::smaller_steps — a process's own step, or analysis.increments); "" for another
  /// cause (a check that failed names its own remedy; a singular tangent has none in the steps).
  std::string advice(const std::string& cause) const;
  /// Every group's tangent choice for an iteration: refactored (in `tangent`) or kept, and why — its residual share
  /// against the policy's threshold, `all_why` when no residuals were taken (every group new), or a constant tangent.
  std::vector<TangentChoice> tangent_choices(const std::vector<size_t>& tangent, const std::vector<double>& share,
                                             const std::string& all_why) const;
  /// A converged step of load-factor span `span` ending at `lf`: the heat conducted over its time (HeatConduction),
  /// the points' temperatures written back into the committed state. `slid_before`: the pairs' slip where it began.
  void heat_step(double span, double lf, const std::vector<std::vector<double>>& slid_before);
  void save() { saved_ = {u_, pairs_, lambda_, lambda_valid_}; }
  /// How a diverged run says its step's halvings (`depth` below the nominal step): cut-backs, and the first step's own.
  std::string halvings(int depth) const;
  /// Under `predictor: extrapolate` (and in an ALE run under `tangent`), u_ moved on by the last converged step's
  /// displacement scaled from its load-factor span to this step's; under `quadratic` along the last three states;
  /// false when there is none yet (the first step) or the option is `tangent` outside ALE.
  bool extrapolate(double span);
  void restore() { std::tie(u_, pairs_, lambda_, lambda_valid_) = saved_; }
  void recover_into(Results& into, double lf) const;
  /// The element of a finite-strain body (`plastic`: of a plastic one) with the smallest corner Jacobian ratio at
  /// load factor lf.
  RemeshDue worst_corner(double lf, bool plastic) const;
  /// With NewtonOptions::remesh_quality: the worst element of a finite-strain plastic body when its corner Jacobian
  /// ratio is below it at load factor lf (the run stops there for a remesh); none otherwise.
  std::optional<RemeshDue> distorted(double lf) const;
  /// Why this run cannot move body motion_->body() under its material (AnalysisError): conducted heat, a
  /// prescribed motion of the body.
  void refuse_ale() const;
  /// The ALE step after the converged step ending at lf (AleStep): the moving body's nodes put back, its state
  /// advected, its displacement zero, its contact points found again; a message when its mesh cannot be put back.
  std::string ale_step(double lf);
  /// After a converged step: the first element whose corner has folded (ratio ≤ 0 while every Gauss point's det J
  /// stayed positive, which is all a step's assembly checks) is remembered for the run's warning.
  void watch_folds(double lf, int increment);
  std::shared_ptr<Model> own_;       // an ALE run's model, whose moving body's reference changes after every step
  const Model& model_;               // own_, or the model as given
  const IncrementMeasure* measure_;  // a process's measures of each increment, told to the observer (may be null)
  const MeshMotion* motion_;         // where a body's nodes go after each step (an ALE run), or null
  SolverStrategy& solver_;
  const UpdatePolicy& policy_;
  AnalysisObserver& obs_;
  const NewtonOptions& opt_;
  GroupLayout layout_;
  ForcingSequence forcing_;         // the interface solve's tolerance per iteration (analysis.forcing)
  std::vector<Eigen::VectorXd> u_;  // free dofs per group, the current iterate
  std::vector<PairState> pairs_;
  std::vector<ConstraintRow> rows_;
  BodyConstraints contact_;
  Eigen::VectorXd lambda_;
  bool lambda_valid_ = false;  // λ belongs to the current constraint rows
  bool assembled_once_ = false;
  bool solved_once_ = false;
  bool refresh_all_ = false;        // after a cut-back: every group gets a new tangent and factor (none is current)
  bool step_sliding_ = false;       // a pair is searched again where each step begins
  bool iteration_sliding_ = false;  // a pair is searched again at every iteration
  bool couple_slip_ = false;        // slipping Coulomb friction in the system's matrix (C_eq), not lagged
  bool search_again_ = false;       // the step converged on projections that moved: search at the iterate
  std::vector<char> unfactored_;    // per group: K was assembled after its last factorization
  std::vector<std::array<int, 3>> row_keys_;      // (pair, slave node, component) of the kept contact rows
  std::vector<Eigen::VectorXd> step_start_;       // every dof of every body where the current step began
  double step_from_ = 0;                          // and its load factor there
  std::vector<Eigen::VectorXd> step_end_guess_;   // and where it may end: the last step's motion repeated
  std::vector<Eigen::VectorXd> previous_, step_;  // the iterate before the last solve, and its correction
  double slope_ = 0;                              // the line search's s(0)
  double assembly_s_ = 0;                         // residual and tangent assembly, over the run
  std::tuple<std::vector<Eigen::VectorXd>, std::vector<PairState>, Eigen::VectorXd, bool> saved_;
  std::vector<Eigen::VectorXd> last_step_;  // the last converged step's displacement and its load-factor span
  double last_span_ = 0;
  std::vector<Eigen::VectorXd> step_before_;  // and the one before it (0 span: none)
  double span_before_ = 0;
  double last_scale_ = 0, attempt_scale_ = 0;  // the residual scale of the last converged step, of the last attempt
  std::vector<NewtonIteration> log_;
  std::unique_ptr<HeatConduction> heat_;  // the bodies that conduct heat (null: none does)
  std::string fold_;           // the first folded corner of a converged step, said as the run's warning ("": none)
  double position_scale_ = 0;  // the largest node coordinate of the model: what its positions' round-off is of
};

void NewtonRun::set_constraints(double lf, bool step_begins) {
  if (step_sliding_ && step_begins)
    follow_contacts(model_, step_start_, pairs_, ContactPair::Sliding::Step,
                    step_end_guess_.empty() ? nullptr : &step_end_guess_);
  if (step_sliding_ && search_again_)
    follow_contacts(model_, body_displacements(lf), pairs_, ContactPair::Sliding::Step);
  search_again_ = false;
  if (iteration_sliding_) follow_contacts(model_, body_displacements(lf), pairs_, ContactPair::Sliding::Iteration);
  if (step_begins) turn_master_surfaces(model_, step_start_, lf - step_from_, pairs_);
  rows_ = contact_rows(model_, pairs_);
  hold_supported_tangents(rows_, layout_.body_dofs());
  contact_ = body_constraints(rows_, layout_.body_dofs(), lf);
  if (couple_slip_) add_coupling(slip_coupling(model_, pairs_, rows_), layout_.body_dofs(), contact_);
  layout_.set_contact(contact_);
  BlockSystem& sys = layout_.system();
  sys.d_reference = sys.d.size() ? sys.d.lpNorm<Eigen::Infinity>() : 0.0;
  for (size_t g = 0; g < sys.groups.size() && sys.d.size(); ++g) {
    const Eigen::VectorXd Cu = sys.groups[g].C * u_[g];
    sys.d_reference = std::max(sys.d_reference, Cu.lpNorm<Eigen::Infinity>());
    sys.d -= Cu;  // C du = d − C u
  }
  // λ stays the multiplier of the same rows while they are those of the same points (their coefficients may move)
  std::vector<std::array<int, 3>> keys;
  for (int r : contact_.kept)
    keys.push_back({rows_[r].pair, pairs_[rows_[r].pair].points[rows_[r].point].slave_node, rows_[r].comp});
  if (keys != row_keys_ || lambda_.size() != sys.num_multipliers()) lambda_valid_ = false;
  sys.lambda_start = multiplier_guess(keys, sys.num_multipliers());
  row_keys_ = std::move(keys);
}

Eigen::VectorXd NewtonRun::multiplier_guess(const std::vector<std::array<int, 3>>& keys, long rows) const {
  const long glue = rows - static_cast<long>(keys.size());  // the subdomains' glue rows follow the contact rows
  if (lambda_.size() != static_cast<long>(row_keys_.size()) + glue) return {};
  std::map<std::array<int, 3>, double> last;
  for (size_t r = 0; r < row_keys_.size(); ++r) last[row_keys_[r]] = lambda_[static_cast<Eigen::Index>(r)];
  Eigen::VectorXd guess = Eigen::VectorXd::Zero(rows);
  for (size_t r = 0; r < keys.size(); ++r)
    if (const auto it = last.find(keys[r]); it != last.end()) guess[static_cast<Eigen::Index>(r)] = it->second;
  guess.tail(glue) = lambda_.tail(glue);
  return guess;
}

std::string NewtonRun::assemble(const std::vector<size_t>& which, const std::vector<size_t>& tangent,
                                GroupAssembler::Factors at) {
  Stopwatch watch;
  InvertedElement bad;
  try {
    bad = layout_.assembler().assemble_newton(which, tangent, u_, at, layout_.system());
  } catch (const std::runtime_error& e) {  // a material that cannot update at this iterate: the step is cut back
    assembly_s_ += watch.seconds();
    return std::string("the material update failed: ") + e.what();
  }
  assembly_s_ += watch.seconds();
  for (size_t g : tangent) unfactored_[g] = 1;
  if (!bad) {
    add_friction(which);
    return "";
  }
  // named in the body's numbers (the `jacobian_ratio` field's cells), and its FETI subdomain where it has one
  const GroupSource& source = layout_.assembler().source(static_cast<size_t>(bad.group));
  const int element = source.body_elements.empty() ? bad.element : source.body_elements[bad.element];
  const std::string& body = model_.bodies[static_cast<size_t>(source.model_body)].name;
  const std::string& group = layout_.system().groups[bad.group].name;
  return "element " + std::to_string(element) + " of body '" + body + "'" +
         (group == body ? "" : " (in subdomain '" + group + "')") + " is inverted (det J ≤ 0)";
}

void NewtonRun::add_friction(const std::vector<size_t>& which) {
  std::vector<Eigen::VectorXd> load =
      friction_loads(model_, pairs_, couple_slip_ ? FrictionLoads::Capped : FrictionLoads::All);
  if (load.empty()) return;
  for (size_t b = 0; b < load.size(); ++b) load[b] = layout_.body_dofs()[b]->restrict_to_free(load[b]);
  layout_.add_body_load(load, which);
}

bool NewtonRun::prescribed_moves(size_t g, GroupAssembler::Factors at) const {
  if (at.prescribed_step == 0.0) return false;
  const DofMap& dofs = *layout_.body_dofs()[layout_.system().groups[g].body];  // the body's: its subdomains alike
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dofs.num_free());
  return (dofs.expand(zero, at.prescribed + at.prescribed_step) - dofs.expand(zero, at.prescribed))
             .cwiseAbs()
             .maxCoeff() > 0;
}

void NewtonRun::add_contact_stiffness(double lf, const std::vector<size_t>& tangent) {
  BlockSystem& sys = layout_.system();
  const bool full = opt_.contact_tangent == ContactTangent::Full;
  // The friction direction's turn (3D) joins slave and master under `groups` too wherever the solver can take it: one
  // global matrix in its coupling, `mixed` as compliant rows. Without its slave–master part Newton on a 3D Coulomb
  // pass stalls (a 2-cycle under mixed, halving residuals under direct); the others get its parts within one group.
  const bool joined = full || solver_.assembles_globally();
  if (joined) sys.coupling = SparseMatrix();
  layout_.set_compliant({}, {});
  if (opt_.contact_tangent == ContactTangent::None) return;
  std::vector<StiffnessEntry> turn;  // any sliding, 3D
  if (joined || !solver_.solves_compliant()) {
    turn = slip_direction_stiffness(model_, pairs_);
  } else if (const SlipDirectionRows r = slip_direction_rows(model_, pairs_);
             !layout_.set_compliant(r.rows, r.stiffness)) {
    turn = slip_direction_stiffness(model_, pairs_);  // a torn body: its parts within one subdomain
  }
  std::vector<StiffnessEntry> rows;
  const bool rows_follow = iteration_sliding_ && lambda_valid_;
  if (rows_follow)
    rows = contact_geometric_stiffness(model_, pairs_, rows_, contact_.kept, lambda_.head(contact_.d.size()),
                                       body_displacements(lf));
  if (full) {
    turn.insert(turn.end(), rows.begin(), rows.end());
    if (rows_follow || !turn.empty()) layout_.add_body_stiffness(turn, tangent, &sys.coupling);
    return;
  }
  if (!turn.empty()) layout_.add_body_stiffness(turn, tangent, joined ? &sys.coupling : nullptr);
  if (rows_follow) layout_.add_body_stiffness(rows, tangent, nullptr);
}

std::vector<double> NewtonRun::group_residuals() const {
  const BlockSystem& sys = layout_.system();
  std::vector<double> r;
  for (const Group& g : sys.groups)
    r.push_back(lambda_valid_ ? (g.f - g.equation_C().transpose() * lambda_).norm() : g.f.norm());
  return r;
}

std::vector<Eigen::VectorXd> NewtonRun::body_displacements(double lf) const {
  BlockSolution s;
  s.u = u_;
  return full_displacements(layout_.body_dofs(), layout_.body_solution(s), lf);
}

void NewtonRun::heat_step(double span, double lf, const std::vector<std::vector<double>>& slid_before) {
  std::vector<std::vector<double>> states;
  for (size_t b = 0; b < model_.bodies.size(); ++b)
    states.push_back(layout_.assembler().committed_state(static_cast<int>(b), model_.bodies[b].mesh.num_elements()));
  const std::vector<Eigen::VectorXd> u = body_displacements(lf);
  heat_->step({span * opt_.duration, &u, &pairs_, &slid_before}, states);
  for (size_t b = 0; b < model_.bodies.size(); ++b)
    if (!states[b].empty()) layout_.assembler().set_committed_state(static_cast<int>(b), states[b]);
}

void NewtonRun::recover_into(Results& into, double lf) const {
  const std::vector<Eigen::VectorXd> u = body_displacements(lf);
  into.bodies.clear();
  for (size_t b = 0; b < model_.bodies.size(); ++b) {
    const int ne = model_.bodies[b].mesh.num_elements();
    into.bodies.push_back(
        recover(model_, static_cast<int>(b), u[b], lf, layout_.assembler().committed_state(static_cast<int>(b), ne)));
    if (!model_.bodies[b].partition.element_subdomain.empty())
      into.bodies.back().subdomain = model_.bodies[b].partition.element_subdomain;
    if (heat_ && heat_->temperature(static_cast<int>(b)).size() > 0)
      set_nodal_temperature(model_.bodies[b].mesh, heat_->temperature(static_cast<int>(b)), into.bodies.back());
  }
  const Eigen::VectorXd lc =
      lambda_valid_ ? Eigen::VectorXd(lambda_.head(contact_.d.size())) : Eigen::VectorXd::Zero(contact_.d.size());
  contact_results(model_, pairs_, rows_, contact_.kept, lc, into);
  add_contact_reactions(layout_.body_dofs(), rows_, contact_.kept, lc, friction_loads(model_, pairs_), into);
}

RemeshDue NewtonRun::worst_corner(double lf, bool plastic) const {
  const std::vector<Eigen::VectorXd> u = body_displacements(lf);
  RemeshDue worst;
  for (size_t b = 0; b < model_.bodies.size(); ++b) {
    const Body& body = model_.bodies[b];
    if (body.kinematics != Kinematics::Finite || (plastic && !body.material.plastic())) continue;
    for (int e = 0; e < body.mesh.num_elements(); ++e)
      if (const double q = corner_jacobian_ratio(body.mesh, u[b].data(), e); q < worst.quality)
        worst = {static_cast<int>(b), e, q};
  }
  return worst;
}

std::optional<RemeshDue> NewtonRun::distorted(double lf) const {
  if (opt_.remesh_quality <= 0) return std::nullopt;
  const RemeshDue worst = worst_corner(lf, true);
  if (worst.quality >= opt_.remesh_quality) return std::nullopt;
  return worst;
}

void NewtonRun::watch_folds(double lf, int increment) {
  if (!fold_.empty()) return;
  const RemeshDue worst = worst_corner(lf, false);
  if (worst.quality > 0) return;
  fold_ = "body '" + model_.bodies[static_cast<size_t>(worst.body)].name + "': element " +
          std::to_string(worst.element) + " folded a corner in increment " + std::to_string(increment) +
          " (load factor " + four_digits(lf) + "), the first converged step that did (its corner Jacobian ratio " +
          four_digits(worst.quality) +
          ", every Gauss point's still positive; the `jacobian_ratio` cell field): the fields around it are not to be "
          "trusted — a finer mesh there, smaller steps, or analysis.remesh_quality";
}

double norm(const std::vector<double>& parts) {
  double s = 0;
  for (double p : parts) s += p * p;
  return std::sqrt(s);
}

double norm(const std::vector<Eigen::VectorXd>& parts) {
  double s = 0;
  for (const Eigen::VectorXd& p : parts) s += p.squaredNorm();
  return std::sqrt(s);
}

double NewtonRun::energy(const std::vector<Eigen::VectorXd>& du) const {
  const BlockSystem& sys = layout_.system();
  double s = 0;
  for (size_t g = 0; g < du.size(); ++g)
    s += du[g].dot(sys.groups[g].f - sys.groups[g].equation_C().transpose() * lambda_);
  return s;
}

std::string NewtonRun::line_search(const std::vector<size_t>& tangent, GroupAssembler::Factors at, double& eta) {
  const double s1 = energy(step_);
  if (!(slope_ > 0) || std::abs(s1) <= 0.5 * slope_) return "";
  eta = s1 < slope_ ? std::clamp(slope_ / (slope_ - s1), 0.1, 1.0) : 0.5;
  for (size_t g = 0; g < u_.size(); ++g) u_[g] = previous_[g] + eta * step_[g];
  set_constraints(at.load);
  const std::vector<size_t> all = all_groups(layout_.system());
  return assemble(all, tangent, at);
}

int NewtonRun::update_statuses(double lf) {
  if (!has_unilateral(model_)) return 0;
  std::vector<ConstraintRow> kept;
  for (int r : contact_.kept) kept.push_back(rows_[r]);
  const std::vector<Eigen::VectorXd> u_now = body_displacements(lf);
  int changed = update_friction(model_, kept, lambda_.head(contact_.d.size()), u_now, step_start_, pairs_);
  changed +=
      update_active_set(model_, kept, lambda_.head(contact_.d.size()), u_now, pairs_, solver_.multiplier_tolerance());
  if (changed) lambda_valid_ = false;
  return changed;
}

std::vector<TangentChoice> NewtonRun::tangent_choices(const std::vector<size_t>& tangent,
                                                      const std::vector<double>& share,
                                                      const std::string& all_why) const {
  const BlockSystem& sys = layout_.system();
  std::vector<TangentChoice> out;
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    TangentChoice c{sys.groups[g].name, std::find(tangent.begin(), tangent.end(), g) != tangent.end(), ""};
    if (share.empty())
      c.why = all_why;
    else if (!c.refactored && layout_.assembler().constant_tangent(g))
      c.why = "constant";
    else
      c.why = "share " + four_digits(share[g]) + (c.refactored ? " > " : " ≤ ") + four_digits(policy_.threshold());
    out.push_back(std::move(c));
  }
  return out;
}

Iterate NewtonRun::measure(double residual, double first, int k, const std::vector<Eigen::VectorXd>& from) const {
  Iterate it;
  it.relative = first > 0 ? residual / first : 0.0;
  it.balanced = residual == 0.0 || (k > 1 && it.relative <= opt_.tolerance);
  double largest = 0;
  for (size_t g = 0; g < u_.size(); ++g) {
    const Eigen::VectorXd du = u_[g] - from[g];
    it.step += du.squaredNorm();
    if (du.size()) largest = std::max(largest, du.lpNorm<Eigen::Infinity>());
  }
  it.step = std::sqrt(it.step);
  const BlockSystem& sys = layout_.system();
  it.constraint = sys.d.size() ? sys.d.lpNorm<Eigen::Infinity>() : 0.0;  // d − C u at the iterate
  // of the step's displacement, or of the terms d was computed from (a fixed interface tolerance leaves errors of the
  // whole interface's data, which do not shrink with the correction)
  it.constraint_limit = opt_.tolerance * std::max(largest, sys.d_reference);
  return it;
}

std::string NewtonRun::unmet_check(const Iterate& it) const {
  const std::string ratio = "the residual ratio " + four_digits(it.relative);
  if (!it.balanced)  // an interface solved more loosely than Newton's own tolerance stalls the residual too
    return ratio + " is above its tolerance " + four_digits(opt_.tolerance) + " (analysis.tolerance)" +
           (solver_.options().cg_tolerance > opt_.tolerance ? interface_hint() : "");
  const std::string but = ratio + " is within its tolerance " + four_digits(opt_.tolerance) + ", but ";
  if (!lambda_valid_ || it.changed)
    return but + "the contact check failed: " + std::to_string(it.changed) +
           " contact points changed status (in or out, stick or slip) in the last iteration";
  if (it.constraint > it.constraint_limit)
    return but + "the constraint check failed: a contact or glue row is unmet by " + four_digits(it.constraint) +
           ", above analysis.tolerance × the rows' scale (the step's largest displacement, or the terms of their "
           "right-hand side) = " +
           four_digits(it.constraint_limit) + interface_hint();
  const double limit = opt_.displacement_tolerance * it.step;
  if (it.correction > limit)
    return but + "the correction check failed: ‖du‖ = " + four_digits(it.correction) + " is above " +
           four_digits(opt_.displacement_tolerance) + " × the step's displacement " + four_digits(it.step) + " = " +
           four_digits(limit) + interface_hint();
  return "";
}

std::string NewtonRun::unmet_projections(double relative, const ProjectionDrift& drift) const {
  return "the residual ratio " + four_digits(relative) + " is within its tolerance " + four_digits(opt_.tolerance) +
         ", but the projection check failed: " + std::to_string(drift.moved) +
         " contact points are off their projection on the master surface by up to " + four_digits(drift.largest) +
         " (limit " + four_digits(drift.limit) + ", 1e-8 of the pair's search distance)" + interface_hint();
}

std::string NewtonRun::interface_hint() const {
  if (!(solver_.multiplier_tolerance() > kExactInterface)) return "";
  return " — the interface solve leaves constraint errors of its tolerance: a tighter solver.cg_tolerance (now " +
         four_digits(solver_.options().cg_tolerance) + ")";
}

std::string NewtonRun::advice(const std::string& cause) const {
  if (cause.find("is inverted") == std::string::npos) return "";
  const std::string steps = !opt_.smaller_steps.empty()
                                ? opt_.smaller_steps
                                : "more analysis.increments (now " + std::to_string(opt_.increments) + ")";
  return ". An element inverts even in the halved step: take smaller steps from the start — " + steps +
         " — cut-backs halve only the failing step, not the steps that led there";
}

Attempt NewtonRun::attempt(int increment, int attempt_no, double from, double lf) {
  BlockSystem& sys = layout_.system();
  const std::vector<Eigen::VectorXd> u_start = u_;
  step_start_ = body_displacements(from);
  step_from_ = from;
  // under contact_frames: predicted, the stuck contact points' frames are written where the step is expected to end
  // (NewtonOptions.h): frames written where it begins turn with the roll over the step, and the step, converged on
  // them, is searched again and converged again
  step_end_guess_.clear();
  if (opt_.contact_frames == ContactFrames::Predicted && last_span_ > 0) {
    BlockSolution guess;
    guess.u = u_;
    for (size_t g = 0; g < u_.size(); ++g) guess.u[g] += ((lf - from) / last_span_) * last_step_[g];
    step_end_guess_ = full_displacements(layout_.body_dofs(), layout_.body_solution(guess), lf);
  }
  forcing_.restart();
  const bool extrapolated = extrapolate(lf - from);
  new_step(pairs_);
  layout_.assembler().set_step_time((lf - from) * opt_.duration);
  const std::vector<size_t> all = all_groups(sys);
  // the residual's scale; from an extrapolated start, at least the last step's scaled to this one: how far the step
  // is from balance does not depend on how well it was predicted, and the tolerance stays the same force
  double first = extrapolated ? last_scale_ * (lf - from) / last_span_ : 0, correction = 0;
  int changed = 0;
  std::string unmet;            // the check the last iterate failed, with its value and limit
  bool searched_again = false;  // the last iteration only searched the projections again
  for (int k = 1;; ++k) {
    if (obs_.cancel_requested())
      return {{Status::cancelled, Reason::none, "cancelled in increment " + std::to_string(increment)}, "", k - 1};
    set_constraints(lf, k == 1);
    // the first iteration starts from the converged state, the prescribed increment predicted by the tangent (or
    // from the extrapolated state, the prescribed dofs already at lf)
    const bool predict = k == 1 && !extrapolated;
    const GroupAssembler::Factors at{lf, predict ? from : lf, predict ? lf - from : 0.0};
    std::vector<size_t> tangent = all;
    const bool residuals_first = assembled_once_ && !refresh_all_ && policy_.uses_residuals();
    std::vector<double> share;
    const std::string all_why = !assembled_once_ ? "first" : refresh_all_ ? "cut-back" : policy_.name();
    if (residuals_first) {  // the policy decides from the residuals
      if (auto cause = assemble(all, {}, at); !cause.empty()) return {{}, cause, k - 1};
      share = group_residuals();
      const double total = norm(share);
      for (double& x : share) x = total > 0 ? x / total : 0.0;
      tangent.clear();
      for (size_t g : policy_.select(sys, share))  // a constant tangent (elastic, small strain) is never re-assembled
        if (opt_.constant_tangents == ConstantTangents::Refactor || !layout_.assembler().constant_tangent(g))
          tangent.push_back(g);
    }
    // a step's first iteration factors the tangents assembled at the converged iterate of the step before (with its
    // plastic flow) where they are not factored yet: assembled again at the converged state they would be elastic,
    // since a zero strain increment returns elastically. A group whose prescribed dofs move in the step is assembled
    // afresh (every group of its body, so that subdomains do as their body does): its predictor (the prescribed
    // increment times the tangent) and its matrix must be the same tangent.
    std::vector<size_t> fresh = tangent;
    // An extrapolated first iterate has its strain increment, so its own tangent flows: it is assembled there.
    if (opt_.first_tangent == FirstTangent::Converged && k == 1 && assembled_once_ && !refresh_all_ && !extrapolated) {
      std::erase_if(tangent, [&](size_t g) { return !unfactored_[g] && !prescribed_moves(g, at); });
      fresh = tangent;
      std::erase_if(fresh, [&](size_t g) { return !prescribed_moves(g, at); });
    }
    const std::vector<TangentChoice> choices = tangent_choices(tangent, share, all_why);
    if (auto cause = assemble(residuals_first ? fresh : all, fresh, at); !cause.empty()) return {{}, cause, k - 1};
    assembled_once_ = true;
    refresh_all_ = false;
    double eta = 1.0;
    if (k > 1 && opt_.line_search && lambda_valid_) {
      if (auto cause = line_search(tangent, at, eta); !cause.empty()) return {{}, cause, k - 1};
      if (eta != 1.0 && !log_.empty()) log_.back().step_length = eta;
    }
    const double residual = norm(group_residuals());
    if (!std::isfinite(residual)) return {{}, "the residual is not a finite number", k - 1};
    // the scale: the first residual, or the second where the increment is driven by motions that the first does not
    // see (a prescribed rigid body, a moved contact surface: ‖r_1‖ is the last increment's round-off)
    if (k <= 2) first = std::max(first, residual);
    Iterate it = measure(residual, first, k, u_start);
    it.changed = changed, it.correction = correction;
    // a correction at the round-off of the positions changes nothing more: the residual left is the round-off of
    // stiffness times positions. A step whose first solve is all but exact (a 64th of a step from a state in
    // balance) stalls there, below its own scale's tolerance (the 3D window on a fixed roll did, at 2e-7 of it)
    if (k > 2 && !it.balanced && it.relative <= 1e-4 && correction <= 1e-14 * position_scale_) it.balanced = true;
    const double relative = it.relative;
    if (k > 1) obs_.on_newton_iteration(increment, k - 1, relative);
    const bool balanced = it.balanced;
    // the check this iterate fails, kept for the message: a search again after the projection check counts as it
    if (!searched_again || !balanced) unmet = unmet_check(it);
    searched_again = false;
    if (unmet.empty()) {
      const ProjectionDrift drift =
          step_sliding_ ? projection_drift(model_, body_displacements(lf), pairs_) : ProjectionDrift{};
      if (drift.moved == 0) {
        attempt_scale_ = first;
        return {{}, "", k - 1};
      }
      unmet = unmet_projections(relative, drift);
      search_again_ = searched_again = true;  // converged on the step's first projections: iterate on, projected
      changed = 1;                            // where it now is
      continue;
    }
    if (k > 1 && relative > 1e6)
      return {{},
              "the residual grew to " + four_digits(relative) + " times its scale (the larger of its first two values)",
              k - 1};
    if (k > opt_.max_iterations)
      return {{}, "no convergence in " + std::to_string(opt_.max_iterations) + " iterations: " + unmet, k - 1};
    obs_.on_tangents(increment, k, choices);  // told only for an iteration that solves (as convergence.csv's rows)
    add_contact_stiffness(lf, tangent);
    mark_updated(sys, tangent);
    for (size_t g : tangent) unfactored_[g] = 0;
    const long cg_before = solver_.stats().cg_iterations;
    check_floating_groups_held(sys);
    sys.interface_tolerance = forcing_.next(residual, balanced, kEnoughConstraint * it.constraint_limit);
    BlockSolution sol;
    try {  // the first solve's failures are the model's (supports, options): solve_checked names them
      sol = solved_once_ ? solver_.solve(sys, &obs_) : solve_checked(model_, layout_.body_dofs(), solver_, sys, obs_);
    } catch (const SingularMatrix& e) {
      return {{}, tangent_failure(e.what()), k - 1};
    }
    solved_once_ = true;
    // an interface CG that stopped at the round-off level of its data gave the best correction the data allow:
    // Newton takes it, and its own residual judges the step (an inexact Newton step)
    if (!sol.status.ok() && sol.status.reason != Reason::round_off) {
      if (sol.status.status == Status::cancelled) return {sol.status, "", k - 1};
      return {{}, "the linear solve did not converge: " + sol.status.message, k - 1};
    }
    lambda_ = sol.lambda;
    lambda_valid_ = true;
    previous_ = u_;
    step_ = sol.u;
    slope_ = energy(step_);  // du · (r(u) − Cᵀλ) with the new λ: the line search's s(0)
    for (size_t g = 0; g < u_.size(); ++g) u_[g] += sol.u[g];
    correction = norm(sol.u);
    changed = update_statuses(lf);
    log_.push_back({increment, attempt_no, k, lf, residual, relative, correction, 1.0, static_cast<int>(tangent.size()),
                    changed, solver_.stats().cg_iterations - cg_before, describe(choices)});
  }
}

std::string NewtonRun::halvings(int depth) const {
  if (opt_.first_step_halvings == 0)
    return std::to_string(depth) + " cut-backs used (analysis.max_cutbacks: the step halved that often)";
  return "the step halved " + std::to_string(depth) + " times below its nominal size (analysis.max_cutbacks; the run " +
         "starts " + std::to_string(opt_.first_step_halvings) + " below it, analysis.first_step_halvings, and grows " +
         "back)";
}

bool NewtonRun::extrapolate(double span) {
  if (last_span_ <= 0) return false;
  if (opt_.predictor == Predictor::Tangent && !motion_) return false;
  // an ALE run extrapolates by default: the flowing body's step starts on the mesh the last one started on, so the
  // last step's flow is this one's guess (a steady flow repeats it), and the other bodies repeat their last step (a
  // roll turning as before): 15–21 % fewer Newton iterations on the plane-strain windows than the flow alone
  if (opt_.predictor != Predictor::Quadratic || span_before_ <= 0) {
    for (size_t g = 0; g < u_.size(); ++g) u_[g] += (span / last_span_) * last_step_[g];
    return true;
  }
  // the quadratic through the last three converged states (Lagrange, at load factors −s1 − s0, −s1, 0 from here)
  const double s = span, s1 = last_span_, s0 = span_before_;
  const double l1 = -s * (s + s1 + s0) / (s1 * s0), l2 = s * (s + s1) / ((s1 + s0) * s0);
  for (size_t g = 0; g < u_.size(); ++g) u_[g] += -(l1 + l2) * last_step_[g] - l2 * step_before_[g];
  return true;
}

void NewtonRun::refuse_ale() const {
  const int b = motion_->body();
  const std::string name = "ALE: body '" + model_.bodies[static_cast<size_t>(b)].name + "' ";
  if (heat_) throw AnalysisError(name + "cannot carry conducted temperatures yet: remove the heat conduction");
  for (const DisplacementBC& bc : model_.displacements) {
    bool moves = bc.body == b && bc.rotation.has_value();
    for (const std::optional<double>& v : bc.value) moves = moves || (bc.body == b && v.value_or(0.0) != 0.0);
    if (moves)
      throw AnalysisError(name +
                          "has a prescribed motion: its nodes are put back after every step, so only "
                          "supports (zero displacements) can hold it");
  }
}

std::string NewtonRun::ale_step(double lf) {
  const int b = motion_->body();
  const std::vector<Eigen::VectorXd> u = body_displacements(lf);
  std::vector<MeshMotion::Positions> current;
  for (size_t k = 0; k < model_.bodies.size(); ++k) current.push_back(displaced_nodes(model_.bodies[k].mesh, u[k]));
  Body& body = own_->bodies[static_cast<size_t>(b)];
  std::vector<char> touching(static_cast<size_t>(body.mesh.num_nodes()), 0);
  for (size_t i = 0; i < pairs_.size(); ++i)
    for (size_t j = 0; model_.contacts[i].slave_body == b && j < pairs_[i].points.size(); ++j)
      if (pairs_[i].active[j]) touching[static_cast<size_t>(pairs_[i].points[j].slave_node)] = 1;
  AleRemap moved;
  try {
    moved = ale_remap(body, u[static_cast<size_t>(b)], layout_.assembler().committed_state(b, body.mesh.num_elements()),
                      current, touching, *motion_);
  } catch (const AnalysisError& e) {
    return e.what();
  }
  body.mesh.nodes = std::move(moved.nodes);
  layout_.move_nodes(b, body.mesh.nodes);
  if (!moved.state.empty()) layout_.assembler().set_committed_state(b, moved.state);
  const std::vector<Group>& groups = layout_.system().groups;
  for (size_t g = 0; g < groups.size(); ++g)
    if (groups[g].body == b)
      u_[g].setZero();  // its last steps stay: the flow they hold predicts the next (extrapolate)
  refind_contacts(model_, body_displacements(lf), b, pairs_);
  save();
  return "";
}

Results NewtonRun::run() {
  Stopwatch total;
  Results res;
  res.load_increments = opt_.increments;
  res.update_policy = policy_.name();
  for (const Eigen::VectorXd& u : u_) res.dofs += u.size();
  res.rigid_modes = layout_.system().num_rigid_modes();
  res.subdomains = layout_.subdomains();
  res.interface_multipliers = layout_.interface_multipliers();
  res.paper_convention_multipliers = layout_.paper_convention_multipliers();
  const double nominal = 1.0 / opt_.increments;
  // depth: how many times the step is halved below its nominal size. It limits the step, not the run: a long pass
  // may cut back at many node entries, and a step that keeps shrinking across increments still ends
  int increment = 0, depth = opt_.first_step_halvings, attempt_no = 0;
  double lf = 0.0, step = std::ldexp(nominal, -depth);
  while (lf < 1.0) {
    double target = std::min(1.0, lf + step);
    if (1.0 - target < 1e-12) target = 1.0;
    // the count: the steps done and those left at the current step size (more than N after cut-backs)
    const int expected = increment + static_cast<int>(std::ceil((1.0 - lf) / step - 1e-9));
    obs_.on_increment_begin(increment + 1, std::max(expected, increment + 1));
    Attempt a;
    try {
      a = attempt(increment + 1, attempt_no, lf, target);
    } catch (const AnalysisError& e) {  // before any increment, the model as given; after, the increments done stay
      if (increment == 0) throw;
      restore();
      res.status = {Status::error, Reason::none,
                    "increment " + std::to_string(increment + 1) + " (load factor " + four_digits(lf) + " to " +
                        four_digits(target) + "): " + e.what()};
      break;
    }
    if (a.status.status == Status::cancelled) {
      restore();
      res.status = a.status;
      break;
    }
    if (!a.cause.empty()) {
      restore();
      refresh_all_ = true;
      if (depth >= opt_.max_cutbacks) {
        res.status = {Status::diverged, Reason::none,
                      "increment " + std::to_string(increment + 1) + " (load factor " + four_digits(lf) + " to " +
                          four_digits(target) + "): " + a.cause + "; " + halvings(depth) + advice(a.cause)};
        break;
      }
      obs_.on_cutback(increment + 1, a.cause);
      ++depth;
      ++attempt_no;
      step /= 2;
      continue;
    }
    layout_.assembler().commit();
    std::vector<std::vector<double>> slid_before;
    for (const PairState& s : pairs_) slid_before.push_back(s.slid);
    accumulate_slip(model_, body_displacements(target), step_start_, pairs_);
    if (heat_) heat_step(target - lf, target, slid_before);
    step_before_ = last_step_, span_before_ = last_span_;
    last_step_ = u_;
    for (size_t g = 0; g < u_.size(); ++g) last_step_[g] -= std::get<0>(saved_)[g];
    last_span_ = target - lf;
    last_scale_ = attempt_scale_;
    save();
    lf = target;
    ++increment;
    IncrementResults inc;
    inc.load_factor = lf;
    inc.newton_iterations = a.iterations;
    inc.active_set_iterations = a.iterations;
    inc.cutbacks = attempt_no;
    for (const NewtonIteration& it : log_)
      if (it.increment == increment && it.attempt == attempt_no) inc.cg_iterations += it.cg_iterations;
    if (lf < 1.0) {
      Results fields;
      recover_into(fields, lf);
      inc.bodies = std::move(fields.bodies);
      inc.contacts = std::move(fields.contacts);
      if (own_) inc.model = std::make_shared<const Model>(*own_);  // the reference its fields are on
    }
    res.increments.push_back(std::move(inc));
    watch_folds(lf, increment);
    obs_.on_increment_end(increment, increment + static_cast<int>(std::ceil((1.0 - lf) / step - 1e-9)));
    if (measure_ && lf < 1.0) obs_.on_measured(increment, measure_->measure(res.increments.back()));
    obs_.on_progress(lf);
    if (std::string over = measure_ && lf < 1.0 ? measure_->over(res.increments.back()) : ""; !over.empty()) {
      res.status = {Status::converged, Reason::none, over};
      break;
    }
    if (lf < 1.0 && (res.remesh_due = distorted(lf))) break;
    if (motion_ && lf < 1.0) {
      if (const std::string failed = ale_step(lf); !failed.empty()) {
        res.status = {Status::diverged, Reason::none,
                      "after increment " + std::to_string(increment) + " (load factor " + four_digits(lf) +
                          "), the ALE step failed: " + failed};
        break;
      }
      ++res.ale_steps;
    }
    if (attempt_no == 0 && depth > 0) {  // grow back after a cut-back once a step converges at first attempt
      step *= 2;
      --depth;
    }
    attempt_no = 0;
  }
  res.newton = log_;
  res.active_set_iterations = static_cast<int>(log_.size());
  res.multipliers = contact_.d.size();
  res.solver = solver_.stats();
  res.timing.analyze_s = res.solver.analyze_s;
  res.timing.factorize_s = res.solver.factorize_s;
  res.timing.solve_s = res.solver.solve_s;
  res.timing.stiffness_s = assembly_s_;
  if (heat_) {
    res.timing.heat_s = heat_->seconds(), res.timing.heat_factorizations = heat_->factorizations();
    for (std::string& w : heat_->warnings()) res.warnings.push_back(std::move(w));
  }
  if (!fold_.empty()) res.warnings.push_back(fold_);
  const BlockSystem& sys = layout_.system();
  for (size_t g = 0; g < sys.groups.size(); ++g)
    res.stiffness_evaluations[sys.groups[g].name] = layout_.assembler().tangent_evaluations()[g];
  if (increment > 0 || res.status.ok()) {
    obs_.on_stage("recover");
    set_constraints(lf);
    recover_into(res, lf);
    if (own_) res.model = std::make_shared<const Model>(*own_);
    if (res.status.ok() && !res.increments.empty()) {
      res.increments.back().bodies = res.bodies;
      res.increments.back().contacts = res.contacts;
      res.increments.back().model = res.model;
    }
    for (size_t b = 0; res.remesh_due && b < model_.bodies.size(); ++b)
      res.bodies[b].point_state =
          layout_.assembler().committed_state(static_cast<int>(b), model_.bodies[b].mesh.num_elements());
  }
  res.timing.total_s = total.seconds();
  return res;
}

}  // namespace

Results run_newton_static(const Model& model, SolverStrategy& solver, const UpdatePolicy& policy,
                          AnalysisObserver* observer, const NewtonOptions& options, const IncrementMeasure* measure,
                          const MeshMotion* motion) {
  if (model.conducts_heat() && !(options.duration > 0))
    throw AnalysisError(
        "heat conduction needs the analysis's time: give analysis.duration (a rolling pass: "
        "process.roll_speed)");
  if (options.increments < 1 || options.increments > kMaxIncrements)
    throw AnalysisError("increments must be an integer in [1, " + std::to_string(kMaxIncrements) + "], got " +
                        std::to_string(options.increments));
  AnalysisObserver quiet;
  AnalysisObserver& obs = observer ? *observer : quiet;
  obs.on_stage("assemble");
  if (motion) obs.on_stage("ALE: " + motion->describe());
  NewtonRun run(model, solver, policy, obs, options, measure, motion);
  return run.run();
}

}  // namespace rollsim
