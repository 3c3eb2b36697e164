#include "project/RunProject.h"

#include <cmath>

#include "analysis/LinearStatic.h"
#include "analysis/NewtonStatic.h"
#include "analysis/Remeshing.h"
#include "base/Blas.h"
#include "project/ModelBuilder.h"
#include "project/SolverChoice.h"

namespace rollsim {

namespace {
/// Names the first body whose results hold a NaN or an infinity (input magnitudes beyond double precision); "" if none.
std::string non_finite_results(const Model& model, const Results& r) {
  auto finite = [](const auto& values) {
    for (const double v : values)
      if (!std::isfinite(v)) return false;
    return true;
  };
  for (size_t b = 0; b < r.bodies.size(); ++b) {
    const BodyResults& br = r.bodies[b];
    bool ok = br.displacement.allFinite() && br.nodal_force.allFinite();
    for (const auto& s : br.element_stress) ok = ok && finite(s);
    for (const auto& s : br.nodal_stress) ok = ok && finite(s);
    if (!ok)
      return "bodies[" + std::to_string(b) + "]: the results of body '" + model.bodies[b].name +
             "' are not finite numbers: the loads, prescribed displacements, material constants or dimensions are "
             "out of the range double precision can handle";
  }
  return "";
}

/// The strategy's refusal of contact pairs, naming the model's first pair and its kind, when it has any.
void refuse_contact(const SolverStrategy& solver, const Model& model) {
  std::string refusal = solver.contact_refusal();
  if (refusal.empty() || model.contacts.empty()) return;
  const ContactPair& p = model.contacts[0];
  const char* kinds[] = {"tied", "frictionless", "sticking", "coulomb"};
  throw AnalysisError(refusal + " (contacts[0] '" + p.name + "' is " + kinds[static_cast<int>(p.kind)] +
                      (model.contacts.size() > 1 ? ", of " + std::to_string(model.contacts.size()) + " pairs" : "") +
                      ")");
}

Results run_linear(const RunConfig& config, const Model& model, AnalysisObserver* observer,
                   const ProcessRun* /*process: the linear analysis reports no increment measures*/) {
  set_library_threads(config.solver.threads);
  const auto solver = make_solver(config.solver_mode, config.solver);
  refuse_contact(*solver, model);
  return run_linear_static(model, *solver, observer, config.steps.increments, config.steps.max_active_set_iterations);
}

Results run_newton(const RunConfig& config, const Model& model, AnalysisObserver* observer, const ProcessRun* process) {
  set_library_threads(config.solver.threads);
  const auto policy = make_update_policy(config.update);
  const SegmentRun segment = [&](const Model& m, const NewtonOptions& options, AnalysisObserver* told,
                                 const IncrementMeasure* measure) {
    const auto solver = make_solver(config.solver_mode, config.solver);
    refuse_contact(*solver, m);
    return run_newton_static(m, *solver, *policy, told, options, measure, process ? process->mesh_motion() : nullptr);
  };
  if (config.newton.remesh_quality > 0) return run_with_remeshing(model, config.newton, segment, observer, process);
  return segment(model, config.newton, observer, process);
}
}  // namespace

const std::vector<AnalysisInfo>& analysis_registry() {
  static const std::vector<AnalysisInfo> registry = {
      {"linear",
       "small-strain linear elasticity with contact: load increments, each solved to a settled frictionless active "
       "set",
       run_linear},
      {"newton",
       "incremental Newton analysis: J2 plasticity with the consistent tangent, the frictionless active set updated "
       "at every iteration, cut-back of steps that do not converge, the update policy (always / selective) per group",
       run_newton},
  };
  return registry;
}

std::vector<std::string> analysis_names() {
  std::vector<std::string> names;
  for (const AnalysisInfo& a : analysis_registry()) names.push_back(a.name);
  return names;
}

Results run_project(const Project& project, const Model& model, AnalysisObserver* observer) {
  return run_project(project.config(), model, observer);
}

RunStatus process_refusal(const RunConfig& config, const Model& model) {
  return config.process ? config.process->start(config.process_section, model)->refusal() : RunStatus{};
}

Results run_project(const RunConfig& config, const Model& model, AnalysisObserver* observer) {
  if (config.solver_mode == kAutoSolver) {
    const AutoChoice choice = choose_solver_mode(config, model);
    if (observer) observer->on_stage("solver auto: " + choice.reason);
    RunConfig chosen = config;
    chosen.solver_mode = choice.mode;
    Results r = run_project(chosen, model, observer);
    r.auto_choice = choice;
    return r;
  }
  const std::string& type = config.analysis;
  const std::unique_ptr<ProcessRun> process =
      config.process ? config.process->start(config.process_section, model) : nullptr;
  if (process) {
    if (RunStatus refused = process->refusal(); !refused.ok()) {  // an answer, not a failure: nothing is solved
      Results r;
      r.status = std::move(refused);
      return r;
    }
    if (observer) observer->on_measures_begin(process->live_table(), process->live_chart());
  }
  for (const AnalysisInfo& info : analysis_registry())
    if (info.name == type) {
      Results r = info.run(config, model, observer, process.get());
      if (r.status.ok())  // never a NaN in a result: a converged run whose fields overflowed is an error
        if (auto bad = non_finite_results(model, r); !bad.empty()) r.status = {Status::error, Reason::none, bad};
      if (process) r.process = process->finish(r);
      return r;
    }
  throw AnalysisError("analysis.type: no analysis named '" + type + "'");
}

}  // namespace rollsim
