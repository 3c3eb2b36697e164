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
#include "io/PartitionReportJson.h"
#include "io/RollingCsv.h"
#ifdef ROLLSIM_HAVE_GUI
#include "RollingCharts.h"
#endif
#include "io/Summary.h"
#include "model/DofMap.h"
#include "partition/PartitionReport.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"
#include "solve/Blas.h"
#include "solve/DgemmPeak.h"
#include "solve/PetscStrategy.h"
#include "solve/Stopwatch.h"
#include "solve/UpdatePolicy.h"

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

bool is_one_of(const std::string& word, const std::vector<std::string>& words) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

int invalid(const std::string& message) {
  std::cerr << "rollsim: error: " << message << "\n";
  return 2;
}

/// Applies command-line overrides to the project's solver section; returns an error or "".
std::string apply_overrides(Project& p, const RunOptions& o) {
  json& solver = p.data["solver"];
  if (o.solver) {
    try {
      if (*o.solver != kAutoSolver) make_solver(*o.solver, {});
    } catch (const std::invalid_argument& e) {
      return std::string("--solver: ") + e.what();
    }
    solver["mode"] = *o.solver;
  }
  if (o.preconditioner) {
    if (!is_one_of(*o.preconditioner, preconditioner_names()))
      return "--preconditioner: must be " + one_of(preconditioner_names()) + ", got '" + *o.preconditioner + "'";
    solver["preconditioner"] = *o.preconditioner;
  }
  if (o.projector) {
    if (!is_one_of(*o.projector, projector_names()))
      return "--projector: must be " + one_of(projector_names()) + ", got '" + *o.projector + "'";
    solver["projector"] = *o.projector;
  }
  if (o.interface_solver) {
    if (!is_one_of(*o.interface_solver, interface_solver_names()))
      return "--interface-solver: must be " + one_of(interface_solver_names()) + ", got '" + *o.interface_solver + "'";
    solver["interface_solver"] = *o.interface_solver;
  }
  if (o.cg_tolerance) {
    if (!(*o.cg_tolerance > 0 && *o.cg_tolerance < 1))
      return "--cg-tolerance: must be a number in (0, 1), got " + std::to_string(*o.cg_tolerance);
    solver["cg_tolerance"] = *o.cg_tolerance;
  }
  if (o.update) {
    try {
      make_update_policy(*o.update);
    } catch (const std::invalid_argument& e) {
      return std::string("--update: ") + e.what();
    }
    solver["update"] = *o.update;
  }
  if (o.petsc_method) {
    if (!is_one_of(*o.petsc_method, petsc_method_names()))
      return "--petsc-method: must be " + one_of(petsc_method_names()) + ", got '" + *o.petsc_method + "'";
    solver["petsc_method"] = *o.petsc_method;
  }
  if (o.petsc_options) solver["petsc_options"] = *o.petsc_options;
  if (o.partition) {
    const auto eq = o.partition->find('=');
    const std::string body = eq == std::string::npos ? "" : o.partition->substr(0, eq);
    const std::string spec = eq == std::string::npos ? *o.partition : o.partition->substr(eq + 1);
    json& bodies = p.data["bodies"];
    json* target = body.empty() && !bodies.empty() ? &bodies[0] : nullptr;
    for (auto& b : bodies)
      if (!body.empty() && b["name"] == body) target = &b;
    const bool slab = p.data.contains("process") && (body == "slab" || (body.empty() && bodies.empty()));
    if (slab) {
      p.data["process"].erase("slab_partition_map");
      p.data["process"]["slab_partition"] = spec;  // the generated slab
    } else if (!target) {
      return "--partition: no body named '" + body + "'";
    } else {
      target->erase("partition_map");
      (*target)["partition"] = spec;
    }
  }
  if (o.threads) {
    if (*o.threads < 1 || *o.threads > 256)
      return "--threads: must be an integer in [1, 256], got " + std::to_string(*o.threads);
    solver["threads"] = *o.threads;
  }
  return "";
}

std::filesystem::path output_dir(const Project& p, const RunOptions& o) {
  if (o.out) return *o.out;
  if (p.data.at("output").contains("dir")) return p.data["output"]["dir"].get<std::string>();
  return std::filesystem::path("results") / p.name();
}

}  // namespace

int check_command(const std::string& file) {
  try {
    const Project p = load_project(file);
    const Model m = build_model(p);
    std::cout << file << ": valid (" << m.bodies.size() << " bodies, " << m.total_nodes() << " nodes, "
              << m.total_elements() << " elements)\n";
    return 0;
  } catch (const ProjectError& e) {
    return invalid(e.what());
  }
}

namespace {
/// partition.json beside mesh.vtu when a body is partitioned: the window's partition table (counts and predicted
/// cost against one domain) for batch users. An error message, or empty.
std::string write_partition_report(const std::filesystem::path& file, const Model& model) {
  std::vector<BodyPartitionReport> reports;
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    if (b.partition.num_subdomains <= 1) continue;
    const DofMap dofs(b, static_cast<int>(i), model.displacements);
    PartitionReporter reporter(b, dofs);
    reports.push_back({b.name, reporter.update(b.partition)});
  }
  if (reports.empty()) return {};
  try {
    write_file_atomically(file, partition_report_json(reports));
  } catch (const std::exception& e) {
    return "cannot write " + file.string() + ": " + e.what();
  }
  return {};
}
}  // namespace

int mesh_command(const RunOptions& o) {
  Model model;
  Project project;
  try {
    project = load_project(o.project);
    if (auto err = apply_overrides(project, o); !err.empty()) return invalid(err);
    model = build_model(project);
  } catch (const ProjectError& e) {
    return invalid(e.what());
  }
  for (const auto& w : model.warnings) std::fprintf(stderr, "rollsim: warning: %s\n", w.c_str());
  const auto file = output_dir(project, o) / "mesh.vtu";
  try {
    std::filesystem::create_directories(file.parent_path());
    write_mesh_vtu(file, model);
  } catch (const std::exception& e) {
    return invalid("cannot write " + file.string() + ": " + e.what());
  }
  if (const auto err = write_partition_report(file.parent_path() / "partition.json", model); !err.empty())
    return invalid(err);
  if (!o.quiet)
    std::fprintf(stderr, "rollsim: %s: %zu bodies, %ld nodes, %ld elements\n", project.name().c_str(),
                 model.bodies.size(), model.total_nodes(), model.total_elements());
  std::cout << file.string() << "\n";
  return 0;
}

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
    project = load_project(o.project);
    if (auto err = apply_overrides(project, o); !err.empty()) return invalid(err);
  } catch (const ProjectError& e) {
    return invalid(e.what());
  }
  try {  // a strategy the options or this build cannot make (petsc without PETSc) is invalid input
    const std::string mode = project.data.at("solver").at("mode").get<std::string>();
    if (mode != kAutoSolver) make_solver(mode, solver_options(project));
  } catch (const std::invalid_argument& e) {
    return invalid(e.what());
  }
  // solver `petsc` under mpirun: every rank builds the model and its own subdomain; rank 0 reports and writes
  if (project.data.at("solver").at("mode").get<std::string>() == "petsc") start_processes();
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
  const SolverOptions options = solver_options(project);
  RunInfo info{project.name(),         project.data.at("solver").at("mode").get<std::string>(),
               options.cg_tolerance,   options.threads,
               options.preconditioner, options.multipliers,
               options.projector,      blas_description()};
  info.interface_solver = options.interface_solver;
  info.fields = project.data.at("output").value("fields", std::vector<std::string>{});
  const auto dir = output_dir(project, o);
  std::error_code ec;
  if (writer) std::filesystem::create_directories(dir, ec);
  if (ec) return invalid("cannot create output directory " + dir.string() + ": " + ec.message());
  Results results;
  try {
    // petsc: the ranks would stop at different iterations and wait for each other in PETSc: no cancel there
    std::optional<InterruptScope> interrupt;
    if (info.mode != "petsc") interrupt.emplace();
    results = run_project(project, model, &progress);
  } catch (const AnalysisError& e) {
    results.status = {Status::error, Reason::none, e.what()};
  }
  if (!writer) return exit_code(results.status.status);  // the other ranks of a petsc run: rank 0 writes
  if (results.auto_choice) info.mode = results.auto_choice->mode;
  if (results.solver.factor_flops_total > 0) {  // the yardstick of factor_gflops, after the analysis: ~10 ms
    // order 256 for any thread count: the 384 of bench's 2-thread peak took 3x the flops, ~20 ms more of a 0.5 s run
    const DgemmPeak peak = measure_dgemm_peak(options.threads, 256);
    info.dgemm_peak_gflops = peak.gflops;
    info.peak_probe_s = peak.seconds;
  }
  progress.on_stage("write results");
  try {
    clear_run_outputs(dir);  // the folder holds this run only: no result.vtu of an earlier run beside a failure
    if (results.status.ok() && project.data.at("output").at("vtu").get<bool>()) {
      write_vtu(dir / "result.vtu", model, results, info.fields);
      if (results.load_increments > 1 && project.data.at("output").value("increments", "all") == "all")
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
