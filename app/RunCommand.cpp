// `rollsim run`, `rollsim check` and `rollsim mesh`: project -> model (-> analysis -> results) -> writers.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "Commands.h"
#include "Interrupt.h"
#include "PvdWriter.h"
#include "VtuWriter.h"
#include "analysis/LinearStatic.h"
#include "analysis/RollingTheory.h"
#include "io/AtomicFile.h"
#include "io/ConvergenceCsv.h"
#include "io/OutputFolder.h"
#include "io/RollingCsv.h"
#ifdef ROLLSIM_HAVE_GUI
#include "RollingCharts.h"
#endif
#include "base/Blas.h"
#include "base/DgemmPeak.h"
#include "base/Stopwatch.h"
#include "io/Summary.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"
#include "solve/PetscStrategy.h"

namespace rollsim::app {

namespace {

/// Progress on stderr: stage names with the elapsed time; Ctrl-C cancels (InterruptScope).
class StderrProgress final : public AnalysisObserver {
 public:
  explicit StderrProgress(bool quiet) : quiet_(quiet) {}
  void on_stage(const std::string& stage) override {
    if (!quiet_) std::fprintf(stderr, "rollsim: [%7.3f s] %s\n", clock_.seconds(), stage.c_str());
  }
  void on_increment_begin(int increment, int count) override {
    if (!quiet_ && count > 1)
      std::fprintf(stderr, "rollsim: [%7.3f s] increment %d of %d\n", clock_.seconds(), increment, count);
  }
  void on_cutback(int increment, const std::string& cause) override {
    if (!quiet_)
      std::fprintf(stderr, "rollsim: [%7.3f s] increment %d cut back (step halved): %s\n", clock_.seconds(), increment,
                   cause.c_str());
  }
  bool cancel_requested() const override { return InterruptScope::requested(); }

 private:
  bool quiet_;
  Stopwatch clock_;
};

int invalid(const std::string& message) {
  std::cerr << "rollsim: error: " << message << "\n";
  return 2;
}

}  // namespace

namespace {
/// What a rolling engineer reads first: the pass's roll force, torque, forward slip and exit thickness, and whether
/// they are steady (rolling.csv has every increment).
std::string rolling_line(const Model& model, const RollingResults& r) {
  const RollingIncrement& s = r.steady;
  const RollingTheory t = rolling_theory(*model.rolling);
  const bool plane = model.dim == 2;
  char state[120];
  if (r.steady_state_increment)
    std::snprintf(state, sizeof state, "steady from %.4g mm of travel: means from there on",
                  r.increments[static_cast<size_t>(r.steady_state_increment - 1)].travel);
  else
    std::snprintf(state, sizeof state, "last completed increment, %.4g mm of travel: not steady yet",
                  r.increments.back().travel);
  char buf[700];
  std::snprintf(
      buf, sizeof buf,
      "rollsim: rolling: roll force %.4g %s, torque %.4g %s, forward slip %.2f %%, exit thickness %.3f mm, slab "
      "volume change %.1e (%s; rolling.csv, contact_profile.csv and their PNG plots)\n"
      "rollsim: rolling: Sims (sticking friction): roll force %.4g %s, torque %.4g %s, forward slip %.2f %%\n",
      s.roll_force, plane ? "N/mm" : "N", s.roll_torque, plane ? "N·mm/mm" : "N·mm", 100 * s.forward_slip,
      s.exit_thickness, s.volume_change, state, t.sims_force, plane ? "N/mm" : "N", t.sims_torque,
      plane ? "N·mm/mm" : "N·mm", 100 * t.sims_forward_slip);
  if (plane) return buf;
  char spread[200];
  std::snprintf(spread, sizeof spread,
                "rollsim: rolling: spread %.3g mm at the widest point, %.3g mm of the mean width; Wusatowski %.3g mm\n",
                s.spread, s.mean_spread, t.wusatowski_spread);
  return buf + std::string(spread);
}
}  // namespace

int run_command(const RunOptions& o) {
  Stopwatch wall;
  Project project;
  Model model;
  try {
    project = load_project(o.project, o.overrides);
  } catch (const ProjectError& e) {
    return invalid(e.what());
  }
  const RunConfig config = project.config();
  try {  // a strategy the options or this build cannot make (petsc without PETSc) is invalid input
    if (config.solver_mode != kAutoSolver) make_solver(config.solver_mode, config.solver);
  } catch (const std::invalid_argument& e) {
    return invalid(e.what());
  }
  // solver `petsc` under mpirun: every rank builds the model and its own subdomain; rank 0 reports and writes
  if (config.solver_mode == "petsc") start_processes();
  const bool writer = process_rank() == 0;
  StderrProgress progress(o.quiet || !writer);
  try {
    progress.on_stage("build model");
    model = build_model(project);
  } catch (const ProjectError& e) {
    return invalid(e.what());
  }
  if (writer)
    for (const auto& w : model.warnings) std::fprintf(stderr, "rollsim: warning: %s\n", w.c_str());
  RunInfo info{project.name(), config.solver_mode, to_json(config), blas_description()};
  info.fields = config.output.fields;
  const auto dir = output_dir(project, o);
  std::error_code ec;
  if (writer) std::filesystem::create_directories(dir, ec);
  if (ec) return invalid("cannot create output directory " + dir.string() + ": " + ec.message());
  Results results;
  try {
    // petsc: the ranks would stop at different iterations and wait for each other in PETSc: no cancel there
    std::optional<InterruptScope> interrupt;
    if (info.mode != "petsc") interrupt.emplace();
    results = run_project(config, model, &progress);
  } catch (const AnalysisError& e) {
    results.status = {Status::error, Reason::none, e.what()};
  }
  if (!writer) return exit_code(results.status.status);  // the other ranks of a petsc run: rank 0 writes
  if (results.auto_choice) info.mode = results.auto_choice->mode;
  if (results.solver.factor_flops_total > 0) {  // the yardstick of factor_gflops, after the analysis: ~10 ms
    // order 256 for any thread count: the 384 of bench's 2-thread peak took 3x the flops, ~20 ms more of a 0.5 s run
    const DgemmPeak peak = measure_dgemm_peak(config.solver.threads, 256);
    info.dgemm_peak_gflops = peak.gflops;
    info.peak_probe_s = peak.seconds;
  }
  progress.on_stage("write results");
  try {
    clear_run_outputs(dir);  // the folder holds this run only: no result.vtu of an earlier run beside a failure
    if (results.status.ok() && config.output.vtu) {
      write_vtu(dir / "result.vtu", model, results, info.fields);
      if (results.load_increments > 1 && config.output.all_increments)
        write_increment_collection(dir / "results.pvd", model, results, info.fields);
    }
    if (!results.newton.empty()) write_file_atomically(dir / "convergence.csv", convergence_csv(results));
    if (results.rolling) {
      write_file_atomically(dir / "rolling.csv", rolling_csv(*results.rolling));
      write_file_atomically(dir / "contact_profile.csv", contact_profile_csv(*results.rolling));
#ifdef ROLLSIM_HAVE_GUI
      ui::write_rolling_plots(dir, *results.rolling, model.dim, rolling_theory(*model.rolling));
#endif
    }
    results.timing.total_s = wall.seconds();
    write_file_atomically(dir / "summary.json", make_summary(model, results, info).dump(2) + "\n");
  } catch (const std::exception& e) {
    return invalid("cannot write the results into " + dir.string() + ": " + e.what());
  }
  const auto summary = (dir / "summary.json").string();
  // a pass that stopped still says what it measured up to there (rolling.csv has every completed increment)
  const bool measured = results.rolling && !results.rolling->increments.empty() && !o.quiet;
  if (!results.status.ok()) {
    if (measured) std::cerr << rolling_line(model, *results.rolling);
    std::cerr << "rollsim: " << to_string(results.status.status) << ": " << results.status.message
              << " (summary written to " << summary << ")\n";
    return exit_code(results.status.status);
  }
  if (!o.quiet)
    std::fprintf(stderr, "rollsim: %s: %ld dofs, solver %s%s, %.3f s; results in %s/\n", project.name().c_str(),
                 results.dofs, info.mode.c_str(), results.auto_choice ? " (auto)" : "", results.timing.total_s,
                 dir.string().c_str());
  if (measured) std::cerr << rolling_line(model, *results.rolling);
  std::cout << summary << "\n";
  return 0;
}

}  // namespace rollsim::app
