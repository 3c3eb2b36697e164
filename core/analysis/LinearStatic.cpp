#include "analysis/LinearStatic.h"

#include <memory>
#include <set>

#include "analysis/ConstraintAssembly.h"
#include "analysis/ContactResults.h"
#include "analysis/GroupLayout.h"
#include "analysis/Recovery.h"
#include "contact/ContactConstraints.h"
#include "model/DofMap.h"
#include "solve/Stopwatch.h"
#include "solve/UpdatePolicy.h"

namespace rollsim {

namespace {
// Names the body, node and component of global equation `col` (groups stacked in order), and what the factorization
// found (`what`).
std::string describe_singular(const Model& model, const std::vector<std::unique_ptr<DofMap>>& dofs, int col,
                              const std::string& what) {
  std::string where;
  int offset = 0;
  for (size_t b = 0; b < dofs.size() && where.empty(); ++b) {
    const DofMap& d = *dofs[b];
    if (col >= offset && col < offset + d.num_free()) {
      const Mesh& m = model.bodies[b].mesh;
      for (int n = 0; n < m.num_nodes() && where.empty(); ++n)
        for (int c = 0; c < m.dim; ++c)
          if (d.equation(n, c) == col - offset) {
            const auto& x = m.nodes[n];
            where = " at body '" + model.bodies[b].name + "', node " + std::to_string(n) + " (" + std::to_string(x[0]) +
                    ", " + std::to_string(x[1]) + (m.dim == 3 ? ", " + std::to_string(x[2]) : "") + "), component " +
                    "xyz"[c];
          }
    }
    offset += d.num_free();
  }
  return "the stiffness matrix is singular" + where + " (to working precision: " + what +
         "): a body or part of it is not held against rigid-body motion (add displacement or symmetry conditions), "
         "or its material is nearly incompressible (Poisson's ratio close to 0.5 needs the B-bar formulation) or "
         "its stiffnesses differ by more than 1e12";
}
}  // namespace

namespace {

/// Load factor of increment i of n: i / n, exactly 1 for the last.
double load_factor(int i, int n) { return i == n ? 1.0 : static_cast<double>(i) / n; }

BlockSolution solve_checked(const Model& model, const std::vector<std::unique_ptr<DofMap>>& dofs,
                            SolverStrategy& solver, const BlockSystem& sys, AnalysisObserver& obs) {
  try {
    return solver.solve(sys, &obs);
  } catch (const SingularMatrix& e) {
    if (sys.num_rigid_modes() > 0)
      throw AnalysisError("the system is singular: the contact constraints do not hold the floating bodies (" +
                          std::to_string(sys.num_rigid_modes()) + " rigid modes; " + e.what() +
                          ") — check that the contact surfaces meet and hold every free direction");
    const bool one_body_per_group = sys.groups.size() == model.bodies.size();
    throw AnalysisError(describe_singular(model, dofs, one_body_per_group ? e.column : -1, e.what()));
  } catch (const std::invalid_argument& e) {
    throw AnalysisError(e.what());
  }
}

std::vector<Eigen::VectorXd> full_displacements(const std::vector<std::unique_ptr<DofMap>>& dofs,
                                                const std::vector<Eigen::VectorXd>& free, double load_factor) {
  std::vector<Eigen::VectorXd> u;
  for (size_t b = 0; b < dofs.size(); ++b) u.push_back(dofs[b]->expand(free[b], load_factor));
  return u;
}

bool has_unilateral(const Model& model) {
  for (const ContactPair& p : model.contacts)
    if (p.kind == ContactKind::Frictionless) return true;
  return false;
}

/// Every rigid mode of a floating group must move some constrained dof: G = [C_g R_g] of full column rank (paper
/// eq. (8) is solvable only then). Checked for every strategy, so that none returns an answer for a body that
/// nothing holds (a frictionless contact cannot hold sideways motion, for one).
void check_floating_groups_held(const BlockSystem& sys) {
  const long k = sys.num_rigid_modes();
  if (k == 0) return;
  // G = [C_g R_g] is sparse (a group's modes touch only its own constraint rows): GᵀG from the sparse G costs
  // O(nnz) where the dense product cost m k² (and a Jacobi SVD of GᵀG k³ with a large constant) — on 2D 120×120
  // in 10×10 subdomains (k = 269) that check took longer than the FETI solve it guards.
  std::vector<Eigen::Triplet<double, int>> t;
  std::vector<std::string> owner;
  for (const Group& g : sys.groups)
    if (g.R.cols()) {
      const Eigen::MatrixXd CR = g.C * g.R;
      const int first = static_cast<int>(owner.size());
      for (int j = 0; j < CR.cols(); ++j)
        for (int i = 0; i < CR.rows(); ++i)
          if (CR(i, j) != 0.0) t.emplace_back(i, first + j, CR(i, j));
      owner.insert(owner.end(), static_cast<size_t>(g.R.cols()), g.name);
    }
  SparseMatrix G(static_cast<int>(sys.num_multipliers()), static_cast<int>(k));
  G.setFromTriplets(t.begin(), t.end());
  const Eigen::MatrixXd GtG = Eigen::MatrixXd(SparseMatrix(G.transpose() * G));
  // GᵀG is symmetric positive semi-definite: its eigenvalues are its singular values
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> values(GtG, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd ev = values.eigenvalues();  // ascending
  if (ev.size() && ev[0] > 1e-10 * std::max(ev[ev.size() - 1], 1e-300)) return;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> vectors(GtG);
  Eigen::Index worst = 0;
  vectors.eigenvectors().col(0).cwiseAbs().maxCoeff(&worst);
  throw AnalysisError(
      "the system is singular: the contact constraints do not hold the floating bodies — a rigid "
      "motion of '" +
      owner[worst] +
      "' moves no constrained dof (check that the contact surfaces "
      "meet and hold every free direction, or add a support)");
}

Multipliers multiplier_choice(const SolverOptions& o) {
  return o.multipliers == "redundant" ? Multipliers::FullyRedundant : Multipliers::NonRedundant;
}
}  // namespace

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
  }

  /// One linear solve with the active set as it stands, at load factor `lf`.
  RunStatus solve_once(double lf) {
    rows = contact_rows(model, pairs);
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
  const std::vector<size_t> selected = AlwaysUpdate().select(sys, {});
  layout.assemble(selected, {}, 1.0);  // K_g and r_g at rest: the linear system
  mark_updated(sys, selected);         // factored on first use, then kept
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
