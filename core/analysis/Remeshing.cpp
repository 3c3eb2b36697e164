#include "analysis/Remeshing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "analysis/AnalysisError.h"
#include "base/Format.h"
#include "fem/Assembler.h"
#include "fem/StateTransfer.h"
#include "material/Material.h"
#include "mesh/ElementQuality.h"
#include "mesh/EvenNodes.h"

namespace rollsim {

namespace {

/// A segment's observer told to the run's: increments numbered on from those before, progress on the run's load
/// factor (a segment's λ covers the run's [base, 1]).
class SegmentObserver final : public AnalysisObserver {
 public:
  SegmentObserver(AnalysisObserver* run, int before, double base) : run_(run), before_(before), base_(base) {}
  void on_stage(const std::string& s) override { run_->on_stage(s); }
  void on_increment_begin(int i, int n) override { run_->on_increment_begin(before_ + i, before_ + n); }
  void on_increment_end(int i, int n) override { run_->on_increment_end(before_ + i, before_ + n); }
  void on_newton_iteration(int i, int k, double r) override { run_->on_newton_iteration(before_ + i, k, r); }
  void on_tangents(int i, int k, const std::vector<TangentChoice>& c) override { run_->on_tangents(before_ + i, k, c); }
  void on_cg_iteration(int s, int k, double r) override { run_->on_cg_iteration(s, k, r); }
  void on_solve_end(int s, int k) override { run_->on_solve_end(s, k); }
  void on_factorization(const std::string& g) override { run_->on_factorization(g); }
  void on_active_set_iteration(int k, int changed) override { run_->on_active_set_iteration(k, changed); }
  void on_cutback(int i, const std::string& cause) override { run_->on_cutback(before_ + i, cause); }
  void on_measured(int i, const MeasureRow& row) override { run_->on_measured(before_ + i, row); }
  void on_progress(double f) override { run_->on_progress(base_ + (1 - base_) * f); }
  bool cancel_requested() const override { return run_->cancel_requested(); }

 private:
  AnalysisObserver* run_;
  int before_;
  double base_;
};

/// A segment's increments measured as the run's (the segment covers the run's load factor [base, 1], its fields are
/// on `model`): what a process measures — its travel, where its slab is — does not restart at a remesh.
class SegmentMeasure final : public IncrementMeasure {
 public:
  SegmentMeasure(const IncrementMeasure& run, std::shared_ptr<const Model> model, double base)
      : run_(run), model_(std::move(model)), base_(base) {}
  MeasureTable live_table() const override { return run_.live_table(); }
  ChartRequest live_chart() const override { return run_.live_chart(); }
  MeasureRow measure(const IncrementResults& increment) const override { return run_.measure(as_run(increment)); }
  std::string over(const IncrementResults& increment) const override { return run_.over(as_run(increment)); }

 private:
  IncrementResults as_run(IncrementResults increment) const {
    increment.load_factor = base_ + (1 - base_) * increment.load_factor;
    if (!increment.model) increment.model = model_;
    return increment;
  }
  const IncrementMeasure& run_;
  std::shared_ptr<const Model> model_;
  double base_;
};

/// What is left of a prescribed motion after load factor `lf`, from where it has taken the nodes.
DisplacementBC rest_of(DisplacementBC bc, double lf) {
  if (bc.rotation) {
    for (int i = 0; i < 3; ++i) bc.rotation->center[i] += lf * bc.value[i].value_or(0.0);
    bc.rotation->angle *= 1 - lf;
  }
  for (std::optional<double>& v : bc.value)
    if (v) *v *= 1 - lf;
  return bc;
}

/// The committed state of a body whose elastic strain must become state to be carried: an elastic finite-strain body
/// goes on as a J2 body that never yields (Hencky's law on b_e = F C_p⁻¹ Fᵀ from C_p⁻¹ = I: the same response), so
/// that its b_e can be its state. Its state (zero: C_p⁻¹ − I) when it has none yet; `state` otherwise.
std::vector<double> as_stateful(Body& body, std::vector<double> state) {
  if (body.material.plastic()) return state;
  body.material.yield_stress = std::numeric_limits<double>::max();
  const int points = body.mesh.dim == 2 ? 4 : 8;
  return std::vector<double>(
      static_cast<size_t>(points) * body.mesh.num_elements() * make_material(body.material)->state_size(), 0.0);
}

/// The nodes of body b's contact surfaces that stay where they are: a master surface's (moved, it would move the
/// surface under the other body's nodes), and a slave surface's facets that touch (a node with `pressure` > 0; every
/// facet when the results hold no pressure) — moved along a chord of their surface, a node there may end up inside
/// the other body: a punch's corner cuts the chord of the surface wrapped around it. A slave facet clear of the other
/// body is spread like any boundary (a rolling slab's head, past the exit, folded its top corner again within a step
/// of each remesh while its whole top stayed).
std::vector<int> contact_nodes(const Model& model, int b, const Eigen::VectorXd& pressure) {
  std::vector<int> nodes;
  const Mesh& mesh = model.bodies[static_cast<size_t>(b)].mesh;
  const bool known = pressure.size() == mesh.num_nodes();
  for (const ContactPair& p : model.contacts) {
    if (p.master_body == b)
      for (int n : surface_nodes(mesh, mesh.surfaces.at(p.master_surface))) nodes.push_back(n);
    if (p.slave_body != b) continue;
    for (const Facet& f : mesh.surfaces.at(p.slave_surface)) {
      std::vector<int> facet;
      for (int l : facet_local_nodes(mesh.type, f.local)) facet.push_back(mesh.element(f.element)[l]);
      if (!known || std::any_of(facet.begin(), facet.end(), [&](int n) { return pressure[n] > 0; }))
        nodes.insert(nodes.end(), facet.begin(), facet.end());
    }
  }
  return nodes;
}

/// The node sets of body b whose every component is prescribed (a face stuck to a tool: a sticking platen's): free
/// boundary nodes that cross their line fold onto them (mesh/EvenNodes).
std::vector<std::vector<int>> stuck_faces(const Model& model, int b) {
  std::vector<std::vector<int>> faces;
  for (const DisplacementBC& bc : model.displacements) {
    bool all = bc.body == b && !bc.rotation;
    for (int c = 0; c < model.dim; ++c) all = all && bc.value[c].has_value();
    if (all) faces.push_back(bc.nodes);
  }
  return faces;
}

/// Why `mesh` (at its own node positions) cannot be a reference — an element folded at a corner —, or "".
std::string folded(const Mesh& mesh) {
  try {
    check_element_orientation(mesh);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

/// The largest value of a point-state component and its integral over the mesh at `x`.
struct CheckField {
  double integral = 0, max = 0;
};
CheckField check_field(const Mesh& m, const std::vector<Point3>& x, const std::vector<double>& state, int width,
                       int component) {
  CheckField c;
  if (component < 0 || width == 0) return c;
  c.integral = integral(m, x, state, width, component);
  for (size_t p = 0; p * width < state.size(); ++p) c.max = std::max(c.max, state[p * width + component]);
  return c;
}

/// The volume mean of nodal values over a quad mesh with its nodes at `x`.
double mean_of_nodal(Mesh m, const std::vector<Point3>& x, const std::vector<double>& nodal) {
  m.nodes = x;
  const std::vector<double> at_points = point_values(m, nodal.data());
  return integral(m, x, at_points, 1, 0) / integral(m, x, std::vector<double>(at_points.size(), 1.0), 1, 0);
}

/// A conducting body's points hold their nodes' temperature (HeatConduction writes it back each step and counts the
/// next step's plastic heat from the difference): the carried nodes' values, not the carried points' — for every
/// body, moved or not (an elastic body's state starts from zero, which would read as its heat taken out: the roll of a
/// rolling pass cooled 10 K in one step after a remesh).
void hold_node_temperatures(Body& moved) {
  if (moved.initial_temperature.empty() || !moved.material.thermal()) return;
  const auto material = make_material(moved.material);
  const int rise = material->temperature_rise_index(), width = material->state_size();
  if (rise < 0) return;
  const std::vector<double> rises = initial_point_rises(moved);
  for (size_t p = 0; p < rises.size(); ++p) moved.initial_state[p * static_cast<size_t>(width) + rise] = rises[p];
}

double worst_shape(const Mesh& m, const std::vector<Point3>& x) {
  double worst = 1;
  for (int e = 0; e < m.num_elements(); ++e) worst = std::min(worst, corner_sine(m, x, e));
  return worst;
}

/// How a later segment's words name its increments and load factors: from the remesh it started at.
std::string after_remesh(int remeshes, double base) {
  return "after remesh " + std::to_string(remeshes) + " (load factor " + four_digits(base) +
         "; increments and load factors below count from it): ";
}

/// A segment's times and solver counts added to the run's.
void add_counts(Results& run, const Results& seg) {
  Timing& t = run.timing;
  const Timing& s = seg.timing;
  t.total_s += s.total_s, t.stiffness_s += s.stiffness_s, t.analyze_s += s.analyze_s, t.factorize_s += s.factorize_s;
  t.solve_s += s.solve_s, t.recovery_s += s.recovery_s, t.heat_s += s.heat_s;
  t.heat_factorizations += s.heat_factorizations;
  SolveStats& a = run.solver;
  for (const auto& [group, n] : seg.solver.factorizations) a.factorizations[group] += n;
  a.cg_iterations += seg.solver.cg_iterations, a.interface_columns += seg.solver.interface_columns;
  a.solves += seg.solver.solves, a.analyze_s += seg.solver.analyze_s, a.factorize_s += seg.solver.factorize_s;
  a.solve_s += seg.solver.solve_s, a.factor_flops_total += seg.solver.factor_flops_total;
  a.factor = seg.solver.factor;
  a.cg_lambda_min = seg.solver.cg_lambda_min, a.cg_lambda_max = seg.solver.cg_lambda_max;
  for (const auto& [group, n] : seg.stiffness_evaluations) run.stiffness_evaluations[group] += n;
  run.active_set_iterations += seg.active_set_iterations;
}

/// The segment's results added to the run's (segment `remeshes`, from the run's load factor `base` on): its
/// increments on the run's load factor, each with the model it was computed on (null: the run's own), its iterations
/// numbered on, its counts added, its warnings and status said from its remesh, its fields the run's last.
void add_segment(Results& run, Results seg, const std::shared_ptr<const Model>& model, int remeshes, double base) {
  const int before = static_cast<int>(run.increments.size());
  auto global = [base](double lf) { return base + (1 - base) * lf; };
  for (IncrementResults& inc : seg.increments) {
    inc.load_factor = global(inc.load_factor);
    inc.model = model;
    run.increments.push_back(std::move(inc));
  }
  for (NewtonIteration& it : seg.newton) {
    it.increment += before;
    it.load_factor = global(it.load_factor);
    run.newton.push_back(std::move(it));
  }
  add_counts(run, seg);
  const std::string from = remeshes > 0 ? after_remesh(remeshes, base) : "";
  for (const std::string& w : seg.warnings)
    if (std::find(run.warnings.begin(), run.warnings.end(), from + w) == run.warnings.end())
      run.warnings.push_back(from + w);
  run.status = std::move(seg.status);
  if (!run.status.ok()) run.status.message = from + run.status.message;
  run.bodies = std::move(seg.bodies);
  run.contacts = std::move(seg.contacts);
  run.model = model;
  run.dofs = seg.dofs, run.multipliers = seg.multipliers, run.rigid_modes = seg.rigid_modes;
  run.subdomains = seg.subdomains, run.interface_multipliers = seg.interface_multipliers;
  run.paper_convention_multipliers = seg.paper_convention_multipliers;
  run.update_policy = seg.update_policy;
  if (remeshes == 0) run.load_increments = seg.load_increments;  // the run's steps as the user asked for them
}

/// The distorted body `b` of `model` moved onto its spread: `moved` (its reference at the current positions `x`, its
/// state `state` read there) gets the spread nodes and the state and temperatures carried onto them — or keeps its
/// nodes where moving them would fold an element (throwing when its current shape has a folded element too).
void spread_body(const Model& model, const Model& original, int b, const std::vector<Point3>& x,
                 const std::vector<double>& state, const Eigen::VectorXd& pressure, Body& moved, RemeshRecord& record) {
  const Body& body = model.bodies[static_cast<size_t>(b)];
  record.body = body.name;
  record.shape_before = worst_shape(body.mesh, x);
  Mesh spread = moved.mesh;
  spread.nodes = even_nodes(original.bodies[static_cast<size_t>(b)].mesh, x, contact_nodes(model, b, pressure),
                            stuck_faces(model, b));
  if (const std::string folds = folded(spread); !folds.empty()) {  // the run goes on from where it is
    record.nodes_kept = "moving them back to their spread would fold an element (" + folds + ")";
    if (const std::string now = folded(moved.mesh); !now.empty())
      throw AnalysisError("body '" + body.name + "' cannot be remeshed: " + now + ", and moving its nodes back to " +
                          "their spread would fold one too (" + folds + ") — a run cannot go on from a folded " +
                          "shape: smaller steps, or an earlier remesh (a higher analysis.remesh_quality)");
  }
  const auto material = make_material(body.material);
  const int width = material->state_size(), alpha = material->equivalent_plastic_strain_index();
  const std::vector<double> temperatures = moved.initial_temperature;
  if (record.nodes_kept.empty()) {
    moved.mesh.nodes = spread.nodes;
    moved.initial_state = transfer_points(body.mesh, x, state, width, moved.mesh);
    if (!moved.initial_temperature.empty())
      moved.initial_temperature = transfer_nodes(body.mesh, x, moved.initial_temperature, moved.mesh);
  }
  if (!moved.initial_temperature.empty()) {
    record.mean_temperature_before = mean_of_nodal(body.mesh, x, temperatures);
    record.mean_temperature_after = mean_of_nodal(moved.mesh, moved.mesh.nodes, moved.initial_temperature);
  }
  const CheckField before = check_field(body.mesh, x, state, width, alpha);
  const CheckField after = check_field(moved.mesh, moved.mesh.nodes, moved.initial_state, width, alpha);
  record.shape_after = worst_shape(moved.mesh, moved.mesh.nodes);
  record.plastic_strain_integral_before = before.integral, record.plastic_strain_integral_after = after.integral;
  record.plastic_strain_max_before = before.max, record.plastic_strain_max_after = after.max;
}
}  // namespace

Model remeshed_model(const Model& model, const Model& original, const Results& done, double lf, RemeshRecord& record) {
  const RemeshDue& due = *done.remesh_due;
  record.element = due.element;
  record.quality = due.quality;
  Model next = model;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const BodyResults& r = done.bodies[b];
    Body& moved = next.bodies[b];
    const std::vector<Point3> x = displaced_nodes(model.bodies[b].mesh, r.displacement);
    const std::vector<double> state = current_state(moved, r.displacement, as_stateful(moved, r.point_state));
    moved.initial_plastic_strain.clear();
    moved.initial_temperature.assign(r.nodal_temperature.data(),
                                     r.nodal_temperature.data() + r.nodal_temperature.size());
    moved.mesh.nodes = x;
    moved.initial_state = state;
    if (static_cast<int>(b) == due.body)
      spread_body(model, original, static_cast<int>(b), x, state, r.contact_pressure, moved, record);
    else if (const std::string now = folded(moved.mesh); !now.empty())
      throw AnalysisError("body '" + moved.name + "' cannot go on from its current shape: " + now);
    hold_node_temperatures(moved);
  }
  for (DisplacementBC& bc : next.displacements) bc = rest_of(bc, lf);
  for (ContactPair& p : next.contacts)  // what is left of a turning master surface's turn
    if (p.master_turns) p.master_turns->angle *= 1 - lf;
  return next;
}

Results run_with_remeshing(const Model& model, const NewtonOptions& options, const SegmentRun& run,
                           AnalysisObserver* observer, const IncrementMeasure* measure) {
  AnalysisObserver silent;
  AnalysisObserver* told = observer ? observer : &silent;
  Results out;
  std::shared_ptr<const Model> current;  // null: the run's own model
  NewtonOptions opt = options;
  double base = 0;
  for (int remeshes = 0;; ++remeshes) {
    const Model& m = current ? *current : model;
    opt.remesh_quality = remeshes < options.max_remeshes ? options.remesh_quality : 0.0;
    SegmentObserver segment(told, static_cast<int>(out.increments.size()), base);
    std::optional<SegmentMeasure> measured;
    if (measure && current) measured.emplace(*measure, current, base);
    Results r = run(m, opt, &segment, measured ? &*measured : measure);
    RemeshRecord record;
    const double lf = r.increments.empty() ? 0.0 : r.increments.back().load_factor;
    std::optional<Model> next;
    if (r.remesh_due) try {
        next = remeshed_model(m, model, r, lf, record);
      } catch (const AnalysisError& e) {
        r.status = {Status::diverged, Reason::none,
                    "the remesh at load factor " + four_digits(base + (1 - base) * lf) + " failed: " + e.what()};
      }
    add_segment(out, std::move(r), current, remeshes, base);
    if (!next) break;
    record.increment = static_cast<int>(out.increments.size());
    record.load_factor = base + (1 - base) * lf;
    out.remeshes.push_back(record);
    told->on_stage("remesh " + std::to_string(remeshes + 1) + " at load factor " + four_digits(record.load_factor) +
                   ": body '" + record.body + "', element " + std::to_string(record.element) +
                   " at corner Jacobian ratio " + four_digits(record.quality) +
                   (record.nodes_kept.empty() ? " (worst corner sine " + four_digits(record.shape_before) + " -> " +
                                                    four_digits(record.shape_after) + ")"
                                              : "; its nodes kept: " + record.nodes_kept));
    base = record.load_factor;
    opt.increments = std::max(1, static_cast<int>(std::lround(options.increments * (1 - base))));
    opt.duration = options.duration * (1 - base);
    current = std::make_shared<const Model>(std::move(*next));
  }
  return out;
}

}  // namespace rollsim
