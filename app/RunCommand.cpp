// `rollsim run`: project -> model -> analysis -> results -> the run writer (core/io/RunWriter), with VTK's field
// writer and cairo's chart sink injected; progress and the process's report on stderr.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "CairoChartSink.h"
#include "Commands.h"
#include "Interrupt.h"
#include "VtkFieldWriter.h"
#include "analysis/AnalysisError.h"
#include "base/Blas.h"
#include "base/DgemmPeak.h"
#include "base/Memory.h"
#include "base/Stopwatch.h"
#include "io/AtomicFile.h"
#include "io/DgemmPeakCache.h"
#include "io/OutputFields.h"
#include "io/RunFolder.h"
#include "io/RunWriter.h"
#include "process/ProcessRegistry.h"
#include "project/ModelBuilder.h"
#include "project/RunProject.h"
#include "solve/Factorization.h"
#include "solve/PetscStrategy.h"
#include "solve/SolverStrategy.h"

namespace rollsim::app {

namespace {

/// Progress on stderr: stage names with the elapsed time; Ctrl-C cancels (InterruptScope).
class StderrProgress final : public AnalysisObserver {
 public:
  StderrProgress(bool quiet, const RunConfig& config) : quiet_(quiet), config_(config) {}
  void on_stage(const std::string& stage) override { say(stage); }
  void on_increment_begin(int increment, int count) override {  // how far, not "of n": n grows with each cut-back
    if (count > 1) say("increment " + std::to_string(increment) + ", " + progress_text(config_, done_) + " done");
  }
  void on_progress(double fraction) override { done_ = fraction; }
  void on_cutback(int increment, const std::string& cause) override {
    say("increment " + std::to_string(increment) + " cut back (step halved): " + cause);
  }
  bool cancel_requested() const override { return interrupt_ && interrupt_->requested(); }
  void listen(const InterruptScope* interrupt) { interrupt_ = interrupt; }

 private:
  void say(const std::string& what) const {
    if (!quiet_) std::fprintf(stderr, "rollsim: [%7.3f s] %s\n", clock_.seconds(), what.c_str());
  }
  bool quiet_;
  const RunConfig& config_;
  double done_ = 0;  // the load factor of the last completed increment
  Stopwatch clock_;
  const InterruptScope* interrupt_ = nullptr;
};

int invalid(const std::string& message) {
  std::cerr << "rollsim: error: " << message << "\n";
  return 2;
}

/// A run that ended in `error` before it had results.
Results failed(const std::string& message, StderrProgress& progress) {
  progress.listen(nullptr);
  Results r;
  r.status = {Status::error, Reason::none, message};
  return r;
}

/// The analysis, its failure to start (or to get memory) an error status; a petsc run cannot be cancelled (its ranks
/// would stop at different iterations and wait for each other in PETSc).
Results analyse(const RunConfig& config, const Model& model, StderrProgress& progress) {
  try {
    std::optional<InterruptScope> interrupt;
    if (config.solver_mode != "petsc") interrupt.emplace();
    progress.listen(interrupt ? &*interrupt : nullptr);
    Results results = run_project(config, model, &progress);
    progress.listen(nullptr);
    return results;
  } catch (const AnalysisError& e) {
    return failed(e.what(), progress);
  } catch (const OutOfMemory& e) {
    return failed(e.what(), progress);
  } catch (const std::bad_alloc&) {
    return failed("out of memory: an allocation failed (" + gigabytes(memory_left_bytes()) + " left to this run by " +
                      memory_left_source() + ") — a coarser mesh, or a machine with more memory",
                  progress);
  }
}

/// What the run says on stderr as it ends: its process's report, its status or where the results went.
int report(const Project& project, const Results& results, const RunStatus& ended, const RunInfo& info,
           const std::filesystem::path& dir, bool quiet) {
  const auto summary = (dir / "summary.json").string();
  if (!quiet && results.process)  // a pass that stopped still says what it measured up to there
    for (const std::string& line : results.process->report) std::cerr << "rollsim: " << line << "\n";
  if (!ended.ok()) {
    std::cerr << "rollsim: " << to_string(ended.status) << ": " << ended.message << " (summary written to " << summary
              << ")\n";
    return exit_code(ended.status);
  }
  if (!quiet && !results.status.message.empty())  // converged short of its load: the process ended it, and why
    std::cerr << "rollsim: " << results.status.message << "\n";
  if (!quiet)
    std::fprintf(stderr, "rollsim: %s: %ld dofs, solver %s%s, %.3f s; results in %s/\n", project.name().c_str(),
                 results.dofs, info.mode.c_str(), results.auto_choice ? " (auto)" : "", results.timing.total_s,
                 dir.string().c_str());
  std::cout << summary << "\n";
  return 0;
}

/// What the results will take on disk at least: result.vtu and, when every increment is written, one VTU each.
double output_bytes(const Model& model, const RunConfig& config) {
  if (!config.output.vtu) return 0;
  const double files = 1 + (config.output.all_increments ? config.steps.increments : 0);
  return files * vtu_bytes(model, config.output.fields);
}

/// The run's files through the run writer, Ctrl-C meaning "stop after this file"; then the report.
int write_results(const Project& project, const RunConfig& config, const Model& model, Results& results,
                  const std::filesystem::path& dir, const nlohmann::json& stamp, const RunOptions& o,
                  const Stopwatch& wall, StderrProgress& progress) {
  RunInfo info;
  info.project = project.name();
  info.mode = results.auto_choice ? results.auto_choice->mode : config.solver_mode;
  info.config = to_json(config);
  info.blas = blas_description();
  info.fields = config.output.fields;
  info.run = stamp;
  if (results.solver.factor_flops_total > 0) {  // the yardstick of factor_gflops: measured once per machine
    const DgemmPeak peak = cached_dgemm_peak(config.solver.threads, 256, default_cache_dir());
    info.dgemm_peak_gflops = peak.gflops, info.peak_probe_s = peak.seconds;
  }
  const VtkFieldWriter fields(config.output.compression);
  const charts::CairoChartSink charts;
  const InterruptScope interrupt(InterruptScope::Phase::writing);
  progress.on_stage("write results");  // from here a signal ends the writing between two files
  try {
    results.timing.total_s = wall.seconds();
    const RunStatus ended =
        write_run(dir, model, results, info, config.output, {&fields, &charts, [&] { return interrupt.requested(); }});
    return report(project, results, ended, info, dir, o.quiet);
  } catch (const WriteError& e) {
    return invalid("cannot write the results into " + dir.string() + ": " + e.what());
  }
}

}  // namespace

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
  return write_results(project, config, model, results, dir, stamp, o, wall, progress);
}

}  // namespace rollsim::app
