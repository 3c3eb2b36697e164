#pragma once
// The steps of `rollsim run` that a single run and a schedule's passes share: progress on stderr, the analysis with
// its failures as statuses, and the run's files through the run writer with the report that ends them.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "Commands.h"
#include "Interrupt.h"
#include "analysis/Results.h"
#include "base/Observer.h"
#include "base/Stopwatch.h"
#include "model/Model.h"
#include "project/RunConfig.h"

namespace rollsim::app {

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

/// "rollsim: error: MESSAGE" on stderr; exit code 2 (invalid input).
int invalid(const std::string& message);

/// The analysis, its failure to start (or to get memory) an error status; a petsc run cannot be cancelled (its ranks
/// would stop at different iterations and wait for each other in PETSc).
Results analyse(const RunConfig& config, const Model& model, StderrProgress& progress);

/// What the results will take on disk at least: result.vtu and, when every increment is written, one VTU each.
double output_bytes(const Model& model, const RunConfig& config);

/// The run's files through the run writer, Ctrl-C meaning "stop after this file"; then the report. The exit code.
int write_results(const Project& project, const RunConfig& config, const Model& model, Results& results,
                  const std::filesystem::path& dir, const nlohmann::json& stamp, const RunOptions& o,
                  const Stopwatch& wall, StderrProgress& progress);

/// `rollsim run` of a schedule (process.passes): each pass a run of its own into DIR/pass-<n>/, then the schedule's
/// table, chart and summary in DIR.
int run_schedule(const RunOptions& o, const Project& project, const Stopwatch& wall);

}  // namespace rollsim::app
