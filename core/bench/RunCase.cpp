#include "bench/RunCase.h"

#include <cmath>
#include <exception>

#include "analysis/AnalysisError.h"
#include "base/Stopwatch.h"
#include "bench/MeshDistortion.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace rollsim::bench {

namespace {

bool all_finite(const Results& r) {
  for (const BodyResults& b : r.bodies) {
    if (!b.displacement.allFinite()) return false;
    for (const auto& s : b.nodal_stress)
      for (double v : s)
        if (!std::isfinite(v)) return false;
  }
  return true;
}

Eigen::VectorXd stacked_displacements(const Results& r) {
  long n = 0;
  for (const BodyResults& b : r.bodies) n += b.displacement.size();
  Eigen::VectorXd u(n);
  long at = 0;
  for (const BodyResults& b : r.bodies)
    u.segment(at, b.displacement.size()) = b.displacement, at += b.displacement.size();
  return u;
}

/// ‖u − u_direct‖ / ‖u_direct‖ with `direct` on the same model (NaN when direct does not converge).
double direct_difference(const SuiteCase& c, const Model& model, const Results& r) {
  json j = c.project;
  j["solver"] = {{"mode", "direct"}, {"threads", 1}};
  const Results d = run_project(parse_project(j.dump(), c.name() + " (direct)"), model);
  if (!d.status.ok()) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::VectorXd ud = stacked_displacements(d), u = stacked_displacements(r);
  if (ud.size() != u.size() || ud.norm() == 0) return std::numeric_limits<double>::quiet_NaN();
  return (u - ud).norm() / ud.norm();
}

void copy_counts(const Results& r, CaseOutcome& o) {
  o.dofs = r.dofs, o.multipliers = r.multipliers, o.subdomains = r.subdomains, o.rigid_modes = r.rigid_modes;
  o.cg_iterations = r.solver.cg_iterations;
  for (const auto& [group, n] : r.solver.factorizations) o.factorizations += n;
  o.newton_iterations = static_cast<int>(r.newton.size());
  o.active_set_iterations = r.active_set_iterations;
  if (r.solver.cg_lambda_min > 0) o.condition = r.solver.cg_lambda_max / r.solver.cg_lambda_min;
}

void run_into(const SuiteCase& c, CaseOutcome& o) {
  const Project project = parse_project(c.project.dump(), c.name());
  Model model = build_model(project);
  if (c.distortion > 0) {
    for (Body& b : model.bodies) distort_interior_nodes(b.mesh, c.distortion, 12345);
    for (const Body& b : model.bodies) check_element_orientation(b.mesh);
  }
  Stopwatch clock;
  const Results r = run_project(project, model);
  o.wall_s = clock.seconds();
  copy_counts(r, o);
  o.status = to_string(r.status.status);
  o.message = r.status.message;
  if (!r.status.ok()) return;
  const Measure m = c.measure(model, r);
  o.value = m.value, o.exact = m.exact;
  if (!all_finite(r) || !std::isfinite(m.value)) {
    o.status = "non_finite";
    o.message = "the run said converged but its answer holds NaN or Inf";
    return;
  }
  if (c.compare_to_direct) o.solver_error = direct_difference(c, model, r);
}

double number(const json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : CaseOutcome::nan;
}

}  // namespace

json to_json(const CaseOutcome& o) {
  auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  return {{"status", o.status},
          {"message", o.message},
          {"wall_s", num(o.wall_s)},
          {"peak_rss_mb", num(o.peak_rss_mb)},
          {"dofs", o.dofs},
          {"multipliers", o.multipliers},
          {"subdomains", o.subdomains},
          {"rigid_modes", o.rigid_modes},
          {"cg_iterations", o.cg_iterations},
          {"factorizations", o.factorizations},
          {"newton_iterations", o.newton_iterations},
          {"active_set_iterations", o.active_set_iterations},
          {"value", num(o.value)},
          {"exact", num(o.exact)},
          {"solver_error", num(o.solver_error)},
          {"condition", num(o.condition)}};
}

CaseOutcome outcome_from_json(const json& j) {
  CaseOutcome o;
  o.status = j.at("status").get<std::string>();
  o.message = j.at("message").get<std::string>();
  o.wall_s = number(j, "wall_s"), o.peak_rss_mb = number(j, "peak_rss_mb");
  o.dofs = j.at("dofs").get<long>(), o.multipliers = j.at("multipliers").get<long>();
  o.subdomains = j.at("subdomains").get<long>(), o.rigid_modes = j.at("rigid_modes").get<long>();
  o.cg_iterations = j.at("cg_iterations").get<long>(), o.factorizations = j.at("factorizations").get<long>();
  o.newton_iterations = j.at("newton_iterations").get<int>();
  o.active_set_iterations = j.at("active_set_iterations").get<int>();
  o.value = number(j, "value"), o.exact = number(j, "exact");
  o.solver_error = number(j, "solver_error"), o.condition = number(j, "condition");
  return o;
}

CaseOutcome run_case(const SuiteCase& c) {
  CaseOutcome o;
  try {
    run_into(c, o);
  } catch (const AnalysisError& e) {
    o.status = "error", o.message = e.what();
  } catch (const std::exception& e) {
    o.status = "error", o.message = std::string("refused: ") + e.what();
  }
  return o;
}

}  // namespace rollsim::bench
