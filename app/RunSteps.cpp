// The steps of `rollsim run` that a single run and a schedule's passes share (RunSteps.h).
#include "RunSteps.h"

#include <cstdio>
#include <iostream>
#include <optional>

#include "CairoChartSink.h"
#include "VtkFieldWriter.h"
#include "analysis/AnalysisError.h"
#include "base/Blas.h"
#include "base/DgemmPeak.h"
#include "base/Memory.h"
#include "io/AtomicFile.h"
#include "io/DgemmPeakCache.h"
#include "io/OutputFields.h"
#include "io/RunWriter.h"
#include "project/RunProject.h"
#include "solve/Factorization.h"

namespace rollsim::app {

int invalid(const std::string& message) {
  std::cerr << "rollsim: error: " << message << "\n";
  return 2;
}

namespace {
/// A run that ended in `error` before it had results.
Results failed(const std::string& message, StderrProgress& progress) {
  progress.listen(nullptr);
  Results r;
  r.status = {Status::error, Reason::none, message};
  return r;
}

}  // namespace

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

namespace {
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

}  // namespace

double output_bytes(const Model& model, const RunConfig& config) {
  if (!config.output.vtu) return 0;
  const double files = 1 + (config.output.all_increments ? config.steps.increments : 0);
  return files * vtu_bytes(model, config.output.fields);
}

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

}  // namespace rollsim::app
