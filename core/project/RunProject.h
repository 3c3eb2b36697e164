#pragma once
// The one run entry point: project -> (model) -> analysis -> results, called by `rollsim run`, the window's worker
// and anything else that runs a project, so that none of them assembles the pipeline for itself. The analysis is
// chosen by name from a registry (analysis.type: `linear` today; the nonlinear issue adds `newton`), the solver
// strategy by name from the solver registry, with the library threads set from solver.threads.
#include <functional>
#include <string>
#include <vector>

#include "analysis/Results.h"
#include "base/Observer.h"
#include "model/Model.h"
#include "process/Process.h"
#include "project/Project.h"

namespace rollsim {

/// One kind of analysis: what it does, and how it runs a built model with the project's settings.
struct AnalysisInfo {
  std::string name;
  std::string description;
  // a process's run (may be null) measures the increments and may move a body's mesh (ProcessRun::mesh_motion)
  std::function<Results(const RunConfig&, const Model&, AnalysisObserver*, const ProcessRun*)> run;
};

/// Every analysis, in the order shown to users, and their names (analysis.type).
const std::vector<AnalysisInfo>& analysis_registry();
std::vector<std::string> analysis_names();

/// Runs `model` (built from `project` by build_model) with the project's analysis and solver, reporting to
/// `observer` (may be null; it also carries the cancel request). Results::status says how it ended; throws
/// AnalysisError for a model that cannot be solved as given. solver.mode `auto` is resolved here
/// (choose_solver_mode), said to the observer as a stage and returned in Results::auto_choice.
Results run_project(const Project& project, const Model& model, AnalysisObserver* observer = nullptr);
/// The same with a configuration of one's own (the project's, changed: the window's solver choice).
Results run_project(const RunConfig& config, const Model& model, AnalysisObserver* observer = nullptr);

/// Why the project's process refuses to be solved on `model` (e.g. a pass the roll cannot bite: no_bite), or
/// converged when it may be solved or has no process: what `rollsim check` and run_project both ask before solving.
RunStatus process_refusal(const RunConfig& config, const Model& model);

}  // namespace rollsim
