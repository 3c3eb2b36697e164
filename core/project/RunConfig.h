#pragma once
// A run's description, typed and parsed once from the validated project (Project::config): the analysis, the solver
// and its options, the update policy, the load steps and the Newton options, and what is written. The analyses, the
// strategies, the writers and summary.json read this, never the JSON; every default is the typed member's, which the
// schema shows and fills in (solve/SolverOptions.h, analysis/NewtonOptions.h, analysis/IncrementOptions.h).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/IncrementOptions.h"
#include "analysis/NewtonOptions.h"
#include "io/OutputConfig.h"
#include "process/Process.h"
#include "solve/SolverOptions.h"
#include "solve/UpdatePolicy.h"

namespace rollsim {

struct RunConfig {
  std::string analysis;     // linear or newton (analysis.type `auto` resolved from the materials)
  std::string solver_mode;  // a registry name, or `auto` (run_project resolves it from the model)
  SolverOptions solver;
  UpdateSetting update;    // Newton's update policy
  IncrementOptions steps;  // analysis.increments (a rolling pass: from its travel) and the active-set limit
  NewtonOptions newton;    // newton.increments = steps.increments
  OutputConfig output;
  const Process* process = nullptr;   // process.type from the registry (null: none)
  nlohmann::json process_section;     // its validated section, what ProcessRun is started from
  std::vector<std::string> warnings;  // options that work against each other (model.warnings gets them)
};

/// The configuration of a validated project (defaults filled in, process expanded where it sets the increments).
RunConfig read_run_config(const nlohmann::json& validated_project);

/// How far a run of `config` is at load factor `fraction` (0…1): its process's words ("travel 12.5 of 120 mm"),
/// else "load factor 0.25 of 1". Monotone over a run, whatever the cut-backs: what the progress line shows.
std::string progress_text(const RunConfig& config, double fraction);

/// The resolved configuration as summary.json echoes it (every option, defaults included, in the project's words).
nlohmann::json to_json(const RunConfig& config);

}  // namespace rollsim
