#include "io/Summary.h"

#include <cmath>
#include <set>

#include "analysis/Recovery.h"
#include "io/OutputFields.h"

namespace rollsim {

namespace {
using json = nlohmann::json;

json vec(const double* v, int n) {
  json a = json::array();
  for (int i = 0; i < n; ++i) a.push_back(v[i]);
  return a;
}

json model_section(const Model& m, const Results& r) {
  return {{"dimension", m.dim},
          {"nodes", m.total_nodes()},
          {"elements", m.total_elements()},
          {"dofs", r.dofs},
          {"bodies", m.bodies.size()},
          {"contact_multipliers", r.multipliers},
          {"interface_multipliers", r.interface_multipliers},
          {"interface_multipliers_paper_convention", r.paper_convention_multipliers},
          {"subdomains", r.subdomains},
          {"rigid_modes", r.rigid_modes},
          {"contact_pairs", m.contacts.size()}};
}

// The resultant force on every node set with a displacement condition, per body and set: the reactions.
json reactions_of(const Model& m, const std::vector<BodyResults>& bodies) {
  json reactions = json::object();
  std::set<std::pair<int, std::string>> done;
  for (const DisplacementBC& bc : m.displacements) {
    if (!done.insert({bc.body, bc.set}).second) continue;
    const auto s = set_resultant(bodies[bc.body], m.dim, bc.nodes);
    reactions[m.bodies[bc.body].name][bc.set] = vec(s.data(), m.dim);
  }
  return reactions;
}

json results_section(const Model& m, const Results& r) {
  json probes = json::object();
  for (const Probe& p : m.probes) {
    const Mesh& mesh = m.bodies[p.body].mesh;
    probes[p.name] = {{"body", m.bodies[p.body].name},
                      {"node", p.node},
                      {"position", vec(mesh.nodes[p.node].data(), m.dim)},
                      {"displacement", vec(r.bodies[p.body].displacement.data() + p.node * m.dim, m.dim)}};
    if (const Eigen::VectorXd& T = r.bodies[p.body].nodal_temperature; T.size() > p.node)
      probes[p.name]["temperature"] = T[p.node];
  }
  double umax = 0;
  for (const BodyResults& b : r.bodies) umax = std::max(umax, b.displacement.cwiseAbs().maxCoeff());
  const json reactions = reactions_of(m, r.bodies);
  json contact = json::object();
  for (const ContactResult& c : r.contacts)
    contact[c.name] = {{"normal_force", c.normal_force}, {"tangential_force", c.tangential_force},
                       {"max_pressure", c.max_pressure}, {m.dim == 2 ? "contact_length" : "contact_area", c.measure},
                       {"active_nodes", c.active_nodes}, {"candidate_nodes", c.candidate_nodes}};
  json out = {{"probes", probes}, {"max_abs_displacement", umax}, {"reactions", reactions}, {"contact", contact}};
  for (size_t b = 0; b < r.bodies.size(); ++b)
    if (!r.bodies[b].plastic_strain.empty())
      out["max_plastic_strain"][m.bodies[b].name] =
          *std::max_element(r.bodies[b].plastic_strain.begin(), r.bodies[b].plastic_strain.end());
  for (size_t b = 0; b < r.bodies.size(); ++b)
    if (!r.bodies[b].temperature.empty())
      out["max_temperature"][m.bodies[b].name] =
          *std::max_element(r.bodies[b].temperature.begin(), r.bodies[b].temperature.end());
  return out;
}

bool all_finite(const json& j) {
  if (j.is_number()) return std::isfinite(j.get<double>());
  if (j.is_structured())
    for (const json& v : j)
      if (!all_finite(v)) return false;
  return true;
}

// One increment's probe displacements and reactions (a load–displacement curve), when it kept its fields.
void add_increment_fields(const Model& m, const IncrementResults& inc, json& entry) {
  if (inc.bodies.size() != m.bodies.size()) return;
  json probes = json::object();
  for (const Probe& p : m.probes) probes[p.name] = vec(inc.bodies[p.body].displacement.data() + p.node * m.dim, m.dim);
  json reactions = reactions_of(m, inc.bodies);
  if (!all_finite(probes) || !all_finite(reactions)) return;  // a failed solve's: nothing to draw, JSON has no NaN
  entry["probes"] = probes;
  entry["reactions"] = reactions;
  json temperatures = json::object();  // the probes on bodies that conduct heat
  for (const Probe& p : m.probes)
    if (const Eigen::VectorXd& T = inc.bodies[p.body].nodal_temperature; T.size() > p.node)
      temperatures[p.name] = T[p.node];
  if (!temperatures.empty() && all_finite(temperatures)) entry["probe_temperatures"] = temperatures;
}

// One entry per completed load increment: its load factor, solves, CG iterations, contact resultants, and the
// probes' displacements and the reactions.
json increments_section(const Model& m, const Results& r) {
  json list = json::array();
  for (size_t i = 0; i < r.increments.size(); ++i) {
    const IncrementResults& inc = r.increments[i];
    json contact = json::object();
    for (const ContactResult& c : inc.contacts)
      contact[c.name] = {{"normal_force", c.normal_force}, {"active_nodes", c.active_nodes}};
    json entry = {{"increment", i + 1},
                  {"load_factor", inc.load_factor},
                  {"active_set_iterations", inc.active_set_iterations},
                  {"cg_iterations", inc.cg_iterations},
                  {"contact", contact}};
    if (r.process && r.process->clock.known()) entry[r.process->clock.name] = r.process->clock.at(inc.load_factor);
    if (!r.update_policy.empty()) {  // the Newton driver
      entry["newton_iterations"] = inc.newton_iterations;
      entry["cutbacks"] = inc.cutbacks;
    }
    add_increment_fields(model_of(inc, m), inc, entry);
    list.push_back(entry);
  }
  return list;
}
/// Every remesh of the run (analysis/Remeshing): where, why, the body's shape and the check field before and after.
json remeshes_section(const std::vector<RemeshRecord>& remeshes) {
  json list = json::array();
  for (const RemeshRecord& m : remeshes) {
    list.push_back(
        {{"after_increment", m.increment},
         {"load_factor", m.load_factor},
         {"body", m.body},
         {"element", m.element},
         {"jacobian_ratio", m.quality},
         {"nodes", m.nodes_kept.empty() ? std::string("moved back to their spread") : "kept: " + m.nodes_kept},
         {"worst_corner_sine", {{"before", m.shape_before}, {"after", m.shape_after}}},
         {"plastic_strain_integral",
          {{"before", m.plastic_strain_integral_before},
           {"after", m.plastic_strain_integral_after},
           {"relative_change", m.plastic_strain_integral_before > 0
                                   ? m.plastic_strain_integral_after / m.plastic_strain_integral_before - 1
                                   : 0.0}}},
         {"max_plastic_strain", {{"before", m.plastic_strain_max_before}, {"after", m.plastic_strain_max_after}}}});
    if (std::isfinite(m.mean_temperature_before))
      list.back()["mean_temperature"] = {{"before", m.mean_temperature_before}, {"after", m.mean_temperature_after}};
  }
  return list;
}

/// Groups spread over MPI ranks: each group's rank, and each rank's groups with their factorizations and the seconds
/// they took — the selective update per rank (a rank whose groups converged keeps its factors).
json ranks_section(const SolveStats& st) {
  json holder = json::object(), per_rank = json::array();
  for (const auto& [group, rank] : st.ranks) {
    holder[group] = rank;
    while (static_cast<int>(per_rank.size()) <= rank)
      per_rank.push_back({{"groups", json::array()}, {"factorizations", 0}});
    per_rank[static_cast<size_t>(rank)]["groups"].push_back(group);
    const auto it = st.factorizations.find(group);
    per_rank[static_cast<size_t>(rank)]["factorizations"] =
        per_rank[static_cast<size_t>(rank)]["factorizations"].get<long>() +
        (it == st.factorizations.end() ? 0 : it->second);
  }
  for (size_t r = 0; r < per_rank.size() && r < st.rank_factorize_s.size(); ++r)
    per_rank[r]["factorize_s"] = st.rank_factorize_s[r];
  return {{"group_rank", holder}, {"per_rank", per_rank}};
}
}  // namespace

json make_summary(const Model& model, const Results& r, const RunInfo& run) {
  const SolveStats& st = r.solver;
  json factorizations = json::object();
  for (const auto& [g, n] : st.factorizations) factorizations[g] = n;
  json s = {{"status", to_string(r.status.status)},
            {"project", run.project},
            {"units", "consistent, as in the project file"}};
  if (r.status.reason != Reason::none) s["reason"] = to_string(r.status.reason);
  if (!r.status.message.empty()) s["message"] = r.status.message;
  if (!run.run.is_null()) s["run"] = run.run;
  std::vector<std::string> warnings = model.warnings;  // the model's, then the run's
  warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
  if (!warnings.empty()) s["warnings"] = warnings;
  s["model"] = model_section(model, r);
  const json options = run.config.is_object() ? run.config.value("solver", json::object()) : json::object();
  s["solver"] = {
      {"mode", run.mode},
      {"cg_tolerance", options.value("cg_tolerance", json())},
      {"cg_iterations_total", st.cg_iterations},
      {"newton_iterations", r.update_policy.empty() ? (r.status.ok() ? 1 : 0) : static_cast<long>(r.newton.size())},
      {"increments", r.load_increments},
      {"active_set_iterations", r.active_set_iterations},
      {"factorizations", factorizations},
      {"threads", options.value("threads", json())},
      {"preconditioner", options.value("preconditioner", json())},
      {"multipliers", options.value("multipliers", json())},
      {"projector", options.value("projector", json())},
      {"interface_solver", options.value("interface_solver", json())},
      {"blas", run.blas},
      {"ordering", st.factor.ordering},
      {"factor_nnz", st.factor.nnz_factor},
      {"factor_flops", st.factor.flops},
      {"factor_flops_total", st.factor_flops_total}};
  if (st.factor_flops_total > 0 && r.timing.factorize_s > 0) {  // how much of the machine the factorizations used
    const double rate = st.factor_flops_total / r.timing.factorize_s / 1e9;  // GFlop/s
    s["solver"]["factor_gflops"] = rate;
    if (run.dgemm_peak_gflops > 0) {
      s["solver"]["dgemm_peak_gflops"] = run.dgemm_peak_gflops;
      s["solver"]["factor_peak_fraction"] = rate / run.dgemm_peak_gflops;
    }
  }
  if (r.auto_choice) {  // solver.mode: auto — the mode above is its choice
    json costs = json::object();
    for (const ModeCost& c : r.auto_choice->costs) costs[c.mode] = c.flops;
    s["solver"]["auto"] = {{"chosen", r.auto_choice->mode},
                           {"predicted_flops", costs},
                           {"reason", r.auto_choice->reason},
                           {"choice_s", r.auto_choice->seconds}};
  }
  if (!st.ranks.empty()) s["solver"]["ranks"] = ranks_section(st);
  if (st.interface_columns > 0) s["solver"]["interface_columns"] = st.interface_columns;
  if (st.extra_interface_iterations > 0) s["solver"]["extra_interface_iterations"] = st.extra_interface_iterations;
  if (st.factor.min_pivot_ratio > 0) s["solver"]["min_pivot_ratio"] = st.factor.min_pivot_ratio;
  s["analysis"] = r.update_policy.empty() ? "linear" : "newton";
  if (!r.update_policy.empty()) {
    s["solver"]["update"] = r.update_policy;
    json evaluations = json::object();
    for (const auto& [g, n] : r.stiffness_evaluations) evaluations[g] = n;
    s["solver"]["stiffness_evaluations"] = evaluations;
  }
  if (st.cg_lambda_max > 0)
    s["solver"]["cg_eigenvalue_estimates"] = {
        {"min", st.cg_lambda_min}, {"max", st.cg_lambda_max}, {"condition", st.cg_lambda_max / st.cg_lambda_min}};
  s["timing"] = {{"total_s", r.timing.total_s},     {"stiffness_s", r.timing.stiffness_s},
                 {"analyze_s", r.timing.analyze_s}, {"factorize_s", r.timing.factorize_s},
                 {"solve_s", r.timing.solve_s},     {"recovery_s", r.timing.recovery_s}};
  if (run.peak_probe_s > 0) s["timing"]["peak_probe_s"] = run.peak_probe_s;
  if (r.timing.heat_factorizations > 0) {
    s["timing"]["heat_s"] = r.timing.heat_s;
    s["timing"]["heat_factorizations"] = r.timing.heat_factorizations;
  }
  s["config"] = run.config;  // every option as the run resolved it, defaults included
  s["increments"] = increments_section(model, r);
  if (!r.remeshes.empty()) s["remeshes"] = remeshes_section(r.remeshes);
  if (r.ale_steps > 0) s["ale_steps"] = r.ale_steps;
  if (!r.status.ok()) return s;
  s["results"] = results_section(r.model ? *r.model : model, r);
  if (r.process) s["results"][r.process->process] = r.process->summary;  // its steady values, units, closed forms
  s["fields"] = json::array();  // what result.vtu holds, from the output registry
  for (const OutputField& f : output_fields())
    if (is_present(f, model) && is_selected(f, run.fields))
      s["fields"].push_back(
          {{"name", f.name}, {"location", to_string(f.location)}, {"components", f.components}, {"unit", f.unit}});
  return s;
}

}  // namespace rollsim
