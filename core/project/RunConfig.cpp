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

/// solver.cg_tolerance left unset under Newton: two orders below Newton's residual tolerance. The interface solve's
/// relative residual is the constraint error it leaves (gaps, sticking points' slips) relative to the whole
/// interface's data; Newton's correction and projection checks measure the same error against one step, so a looser
/// solve keeps them from being met at any step size (a rolling pass at 1e-4 diverged after 0.12 mm of travel).
constexpr double kInterfaceTolerancePerNewton = 1e-2;
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
    c.solver.cg_tolerance = kInterfaceTolerancePerNewton * c.newton.tolerance;
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
