// `rollsim run`: project -> model -> analysis -> results -> the run writer (core/io/RunWriter), with VTK's field
// writer and cairo's chart sink injected; progress and the process's report on stderr.
#include <cstdio>
#include <optional>

#include "RunSteps.h"
#include "io/RunFolder.h"
#include "process/ProcessRegistry.h"
#include "process/rolling/RollingSchedule.h"
#include "project/ModelBuilder.h"
#include "project/RunProject.h"
#include "solve/PetscStrategy.h"
#include "solve/SolverStrategy.h"

namespace rollsim::app {

int run_command(const RunOptions& o) {
  Stopwatch wall;
  Project project;
  RunConfig config;
  try {  // the project with the command line's overrides, and a strategy this build and the options can make
    project = load_project(o.project, o.overrides);
    config = project.config();
    if (config.solver_mode != kAutoSolver) make_solver(config.solver_mode, config.solver);
  } catch (const ProjectError& e) {
    return invalid(e.what());
  } catch (const std::invalid_argument& e) {  // petsc in a build without PETSc
    return invalid(e.what());
  }
  if (is_schedule(project.data)) {
    if (config.solver_mode == "petsc") return invalid("a schedule (process.passes) runs in one process: not petsc");
    return run_schedule(o, project, wall);
  }
  // solver `petsc` under mpirun: every rank builds the model and its own subdomain; rank 0 reports and writes
  if (config.solver_mode == "petsc") start_processes();
  const bool writer = process_rank() == 0;
  StderrProgress progress(o.quiet || !writer, config);
  Model model;
  try {
    progress.on_stage("build model");
    model = build_model(project);
  } catch (const ProjectError& e) {
    return invalid(e.what());
  }
  if (writer)
    for (const auto& w : model.warnings) std::fprintf(stderr, "rollsim: warning: %s\n", w.c_str());
  const auto dir = output_dir(project, o);
  const nlohmann::json stamp = RunStamp{o.command, o.project}.to_json();
  std::optional<RunFolder> folder;  // the folder is this run's, and writable, before any work
  try {
    if (writer) {
      folder.emplace(dir, stamp, process_outputs());
      check_free_space(dir, output_bytes(model, config));
    }
  } catch (const FolderError& e) {
    return invalid(e.what());
  }
  Results results = analyse(config, model, progress);
  if (!writer) return exit_code(results.status.status);  // the other ranks of a petsc run: rank 0 writes
  for (const auto& w : results.warnings) std::fprintf(stderr, "rollsim: warning: %s\n", w.c_str());
  return write_results(project, config, model, results, dir, stamp, o, wall, progress);
}

}  // namespace rollsim::app
