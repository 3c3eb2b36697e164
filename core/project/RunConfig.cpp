#include "project/RunConfig.h"

#include <cstdio>

#include "process/ProcessRegistry.h"
#include "project/ModelBuilder.h"

namespace rollsim {

namespace {
/// Every field of a table in the project's words, from the typed value.
template <class S>
json echo(const std::vector<BoundField<S>>& table, const S& value) {
  json out = json::object();
  for (const BoundField<S>& b : table) out[b.field.name] = b.write(value);
  return out;
}
/// A fixed interface tolerance above Newton's own: the interface solve's λ is the total multiplier, so every solve
/// would leave constraint errors of up to that share of the whole interface's data however close Newton is — more
/// than its constraint and projection checks accept (the paper's pass at 1e-4 balanced its residual and then ran out
/// of iterations on the projection check, before the solves went on to the check's bound: InterfaceTolerance::at_most).
std::vector<std::string> forcing_warnings(double cg_tolerance, const NewtonOptions& n) {
  if (n.forcing != Forcing::Fixed || cg_tolerance <= n.tolerance) return {};
  char w[520];
  std::snprintf(w, sizeof w,
                "solver.cg_tolerance %.3g is above analysis.tolerance %.3g: under analysis.forcing 'fixed' every "
                "interface solve leaves errors Newton's checks do not accept, so its steps may be cut back and the "
                "run may diverge (once a residual is balanced, its solves go on until the constraint rows are met: "
                "summary.json solver.extra_interface_iterations); leave it unset (%.3g), or take analysis.forcing "
                "'eisenstat_walker', under which it is only the loosest tolerance",
                cg_tolerance, n.tolerance, kInterfaceTolerancePerNewton * n.tolerance);
  return {w};
}
}  // namespace

RunConfig read_run_config(const json& p) {
  RunConfig c;
  const json d = expand_process(p);  // a rolling pass sets the increments from its travel
  const json& analysis = d.at("analysis");
  const json& solver = d.at("solver");
  const std::string type = analysis.at("type").get<std::string>();
  c.analysis = type != "auto" ? type : nonlinear_because(d).empty() ? "linear" : "newton";
  c.solver_mode = solver.at("mode").get<std::string>();
  c.solver = read_bound(solver_option_fields(), solver);
  c.update = parse_update(solver.at("update").get<std::string>());
  c.steps = read_bound(increment_option_fields(), analysis);
  c.newton = read_bound(newton_option_fields(), analysis);
  c.newton.increments = c.steps.increments;
  if (c.analysis == "newton" && !solver.contains("cg_tolerance"))
    c.solver.cg_tolerance =
        c.newton.forcing == Forcing::Fixed ? kInterfaceTolerancePerNewton * c.newton.tolerance : kLoosestForcing;
  if (c.analysis == "newton") c.warnings = forcing_warnings(c.solver.cg_tolerance, c.newton);
  const json& out = d.at("output");
  if (out.contains("dir")) c.output.dir = out.at("dir").get<std::string>();
  c.output.vtu = out.at("vtu").get<bool>();
  c.output.all_increments = out.at("increments").get<std::string>() == "all";
  c.output.fields = out.at("fields").get<std::vector<std::string>>();
  c.output.compression = out.at("compression").get<std::string>();
  c.process = process_of(p);
  if (c.process) c.process_section = p.at("process");
  if (c.process) c.newton.smaller_steps = c.process->smaller_steps(c.process_section);
  return c;
}

json to_json(const RunConfig& c) {
  json solver = echo(solver_option_fields(), c.solver);
  solver["mode"] = c.solver_mode;
  solver["update"] = to_string(c.update);
  json analysis = echo(increment_option_fields(), c.steps);
  analysis.update(echo(newton_option_fields(), c.newton));
  analysis["type"] = c.analysis;
  return {{"analysis", analysis}, {"solver", solver}};
}

std::string progress_text(const RunConfig& c, double fraction) {
  if (c.process) return c.process->progress(c.process_section, fraction);
  char s[64];
  std::snprintf(s, sizeof s, "load factor %.4g of 1", fraction);
  return s;
}

}  // namespace rollsim
