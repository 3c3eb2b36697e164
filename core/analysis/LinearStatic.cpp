#include "analysis/LinearStatic.h"

#include <memory>
#include <set>

#include "analysis/ConstraintAssembly.h"
#include "analysis/ContactResults.h"
#include "analysis/DriverSteps.h"
#include "analysis/GroupLayout.h"
#include "analysis/Recovery.h"
#include "base/Stopwatch.h"
#include "contact/ContactConstraints.h"
#include "model/DofMap.h"
#include "solve/UpdatePolicy.h"

namespace rollsim {

namespace {
/// The run's state between solves: the block system, the contact search and the last solution (u, λ, rows).
struct DriverState {
  const Model& model;
  SolverStrategy& solver;
  AnalysisObserver& obs;
  GroupLayout& layout;
  std::vector<PairState> pairs;
  std::vector<ConstraintRow> rows;
  BodyConstraints contact;
  BlockSolution sol;
  std::vector<Eigen::VectorXd> u;
  double factor = 1.0;  // load factor of (u, λ, rows)

  /// Fields and contact resultants of the current (u, λ, rows) at `factor`.
  void recover_into(Results& into) const {
    into.bodies.clear();
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      into.bodies.push_back(recover(model, static_cast<int>(b), u[b], factor));
      if (!model.bodies[b].partition.element_subdomain.empty())
        into.bodies.back().subdomain = model.bodies[b].partition.element_subdomain;
    }
    contact_results(model, pairs, rows, contact.kept, sol.lambda.head(contact.d.size()), into);
    add_contact_reactions(layout.body_dofs(), rows, contact.kept, sol.lambda.head(contact.d.size()), {}, into);
  }

  /// One linear solve with the active set as it stands, at load factor `lf`.
  RunStatus solve_once(double lf) {
    rows = contact_rows(model, pairs);
    hold_supported_tangents(rows, layout.body_dofs());
    contact = body_constraints(rows, layout.body_dofs(), lf);
    layout.set_contact(contact);
    check_floating_groups_held(layout.system());
    obs.on_stage("solve");
    sol = solve_checked(model, layout.body_dofs(), solver, layout.system(), obs);
    u = full_displacements(layout.body_dofs(), layout.body_solution(sol), lf);
    factor = lf;
    return sol.status;
  }

  /// The frictionless statuses of every pair, concatenated: what the cycling test compares.
  std::vector<char> active_set() const {
    std::vector<char> all;
    for (const PairState& p : pairs) all.insert(all.end(), p.active.begin(), p.active.end());
    return all;
  }

  /// Updates the active set from (u, λ); returns the number of points that changed.
  int update_contact_statuses() {
    std::vector<ConstraintRow> kept_rows;
    for (int r : contact.kept) kept_rows.push_back(rows[r]);
    return update_active_set(model, kept_rows, sol.lambda.head(contact.d.size()), u, pairs,
                             solver.multiplier_tolerance());
  }
};

std::string where(int inc, int count, int it) {
  std::string w = count > 1 ? "increment " + std::to_string(inc) + " of " + std::to_string(count) + ", " : "";
  return w + "active-set iteration " + std::to_string(it) + ": ";
}

/// Increment `inc` of `count` at load factor `lf`: solves while the frictionless active set changes. Counts its
/// solves into `step`; ends converged, cancelled, or not_converged (a CG that stopped short, an active set that
/// cycles or reaches `max_iterations`).
RunStatus solve_increment(DriverState& st, int inc, int count, double lf, IncrementResults& step, int& solves,
                          int max_iterations) {
  std::set<std::vector<char>> tried{st.active_set()};
  for (int it = 1;; ++it) {
    if (st.obs.cancel_requested())  // before every solve: the last one's (u, λ, rows) stay the results
      return {Status::cancelled, Reason::none, "cancelled before a linear solve"};
    const RunStatus solved = st.solve_once(lf);
    ++solves;
    step.active_set_iterations = it;
    if (!solved.ok()) return {solved.status, solved.reason, where(inc, count, it) + solved.message};
    if (!has_unilateral(st.model)) return {};
    const int changed = st.update_contact_statuses();
    st.obs.on_active_set_iteration(it, changed);
    if (changed == 0) return {};
    if (!tried.insert(st.active_set()).second)
      return {Status::not_converged, Reason::active_set_cycling,
              where(inc, count, it) + "the frictionless active set returned to a set already tried (" +
                  std::to_string(changed) +
                  " points changed status): the contact cannot decide between them at this load step — try more "
                  "increments or a tighter CG tolerance"};
    if (it == max_iterations)
      return {Status::not_converged, Reason::iteration_limit,
              where(inc, count, it) + "the frictionless active set still changed (" + std::to_string(changed) +
                  " points) after " + std::to_string(max_iterations) + " solves (analysis.max_active_set_iterations)"};
  }
}
}  // namespace

Results run_linear_static(const Model& model, SolverStrategy& solver, AnalysisObserver* observer, int increments,
                          int max_active_set_iterations) {
  if (increments < 1 || increments > kMaxIncrements)
    throw AnalysisError("increments must be an integer in [1, " + std::to_string(kMaxIncrements) + "], got " +
                        std::to_string(increments));
  if (max_active_set_iterations < 1)
    throw AnalysisError("max_active_set_iterations must be a positive integer, got " +
                        std::to_string(max_active_set_iterations));
  AnalysisObserver quiet;
  AnalysisObserver& obs = observer ? *observer : quiet;
  Stopwatch total;
  Results res;
  res.load_increments = increments;
  obs.on_stage("assemble");
  Stopwatch t;
  GroupLayout layout(model, solver.uses_subdomains(), multiplier_choice(solver.options()));
  BlockSystem& sys = layout.system();
  const std::vector<size_t> selected = solver.local_groups(AlwaysUpdate().select(sys, {}));
  layout.assemble(selected, {}, 1.0);  // K_g and r_g at rest: the linear system
  layout.assembler().release_assemblers();
  mark_updated(sys, selected);  // factored on first use, then kept
  res.dofs = sys.num_dofs();
  res.rigid_modes = sys.num_rigid_modes();
  res.subdomains = layout.subdomains();
  res.interface_multipliers = layout.interface_multipliers();
  res.paper_convention_multipliers = layout.paper_convention_multipliers();
  res.timing.stiffness_s = t.seconds();
  DriverState st{model, solver, obs, layout, {}, {}, {}, {}, {}, 1.0};
  try {
    st.pairs = search_contacts(model);
  } catch (const std::runtime_error& e) {
    throw AnalysisError(e.what());
  }
  std::vector<Eigen::VectorXd> full_load;  // every group's f at load factor 1 (only needed to scale it)
  if (increments > 1)
    for (const Group& g : sys.groups) full_load.push_back(g.f);
  int solves = 0;
  for (int inc = 1; inc <= increments && res.status.ok(); ++inc) {
    if (inc > 1 && obs.cancel_requested()) {  // before every increment: the previous one stays the result
      res.status = {Status::cancelled, Reason::none, "cancelled before increment " + std::to_string(inc)};
      break;
    }
    const double lf = load_factor(inc, increments);
    if (increments > 1)
      for (size_t g = 0; g < sys.groups.size(); ++g) sys.groups[g].f = lf * full_load[g];
    obs.on_increment_begin(inc, increments);
    IncrementResults step;
    step.load_factor = lf;
    const long cg_before = solver.stats().cg_iterations;
    res.status = solve_increment(st, inc, increments, lf, step, solves, max_active_set_iterations);
    if (!res.status.ok()) break;  // an increment that did not converge is not listed
    obs.on_increment_end(inc, increments);
    obs.on_progress(static_cast<double>(inc) / increments);
    step.cg_iterations = solver.stats().cg_iterations - cg_before;
    if (inc < increments) {  // the last increment's fields are recovered once, below
      Results fields;
      st.recover_into(fields);
      step.bodies = std::move(fields.bodies);
      step.contacts = std::move(fields.contacts);
    }
    res.increments.push_back(std::move(step));
  }
  res.active_set_iterations = solves;
  res.multipliers = st.contact.d.size();
  res.solver = solver.stats();
  const SolveStats& ss = res.solver;
  res.timing.analyze_s = ss.analyze_s;
  res.timing.factorize_s = ss.factorize_s;
  res.timing.solve_s = ss.solve_s;
  // no fields before the first solve, nor of an iterate that is no solution (a CG stopped short may hold NaN)
  if (solves == 0 || (!res.status.ok() && res.status.status != Status::cancelled)) return res;
  obs.on_stage("recover");
  Stopwatch tr;
  st.recover_into(res);
  if (res.status.ok()) {
    res.increments.back().bodies = res.bodies;
    res.increments.back().contacts = res.contacts;
  }
  res.timing.recovery_s = tr.seconds();
  res.timing.total_s = total.seconds();
  return res;
}

}  // namespace rollsim
