// `rollsim run` of a rolling schedule (process.passes): pass after pass, each a run of its own — its project from the
// schedule (process/rolling/RollingSchedule), its model with what the slab brings (cooled in air between passes),
// its analysis and its files in DIR/pass-<n>/ — then DIR/schedule.csv, schedule.png and summary.json.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "CairoChartSink.h"
#include "RunSteps.h"
#include "analysis/AnalysisError.h"
#include "io/AtomicFile.h"
#include "io/OutputFolder.h"
#include "io/RunFolder.h"
#include "io/RunWriter.h"
#include "process/ProcessRegistry.h"
#include "process/rolling/RollingSchedule.h"
#include "project/Overrides.h"
#include "project/SchedulePasses.h"

namespace rollsim::app {

namespace {
std::string pass_folder(size_t k) { return "pass-" + std::to_string(k + 1); }

/// Pass folders of an earlier, longer schedule in `dir`: their run outputs removed, and the folder when then empty
/// (a file the user put there keeps it).
void remove_stale_passes(const std::filesystem::path& dir, size_t passes) {
  for (size_t k = passes;; ++k) {
    const auto old = dir / pass_folder(k);
    if (!std::filesystem::is_directory(old)) return;
    clear_run_outputs(old, process_outputs());
    std::error_code ec;
    std::filesystem::remove(old, ec);  // fails, harmlessly, where something else is left
  }
}

/// The project file as the user wrote it, with the command line's overrides (the validated project has its
/// defaults filled in: the passes' projects are made from what was given, and validated as any project).
nlohmann::json as_given(const RunOptions& o) {
  std::ifstream in(o.project);
  nlohmann::json given = nlohmann::json::parse(in);
  apply_overrides(given, o.overrides);  // they applied once already: no problem left
  return given;
}

/// DIR/schedule.csv, schedule.png and summary.json: how the schedule ended and its passes.
void write_schedule(const std::filesystem::path& dir, const ScheduleRun& schedule, const RunStatus& ended,
                    const nlohmann::json& stamp, const std::string& name, double seconds) {
  const MeasureTable table = schedule.table();
  write_file_atomically(dir / "schedule.csv", measure_csv(table));
  if (!table.rows.empty())
    write_file_atomically(dir / "schedule.png", charts::CairoChartSink().png(schedule.chart(), table));
  nlohmann::json summary = {{"project", name}, {"status", to_string(ended.status)}, {"message", ended.message},
                            {"run", stamp},    {"timing", {{"total_s", seconds}}},  {"schedule", schedule.summary()}};
  write_file_atomically(dir / "summary.json", summary.dump(2) + "\n");
}
}  // namespace

int run_schedule(const RunOptions& o, const Project& project, const Stopwatch& wall) {
  const auto dir = output_dir(project, o);
  const nlohmann::json stamp = RunStamp{o.command, o.project}.to_json();
  std::optional<RunFolder> folder;
  ScheduleRun schedule(project.data, as_given(o));
  try {
    folder.emplace(dir, stamp, process_outputs());
    remove_stale_passes(dir, schedule.passes());
  } catch (const FolderError& e) {
    return invalid(e.what());
  } catch (const std::runtime_error& e) {
    return invalid(e.what());
  }
  RunStatus ended{Status::converged, Reason::none, ""};
  int code = 0;
  for (size_t k = 0; k < schedule.passes() && code == 0; ++k) {
    if (!o.quiet) std::fprintf(stderr, "rollsim: pass %zu of %zu\n", k + 1, schedule.passes());
    PassSetup s;
    try {
      s = set_up_pass(schedule, k, project);
    } catch (const ProjectError& e) {
      return invalid("pass " + std::to_string(k + 1) + ": " + e.what());
    } catch (const AnalysisError& e) {
      return invalid("pass " + std::to_string(k + 1) + ": " + e.what());
    }
    const auto pass_dir = dir / pass_folder(k);
    std::optional<RunFolder> pass_folder_lock;
    try {
      pass_folder_lock.emplace(pass_dir, stamp, process_outputs());
      check_free_space(pass_dir, output_bytes(s.model, s.project.config()));
    } catch (const FolderError& e) {
      return invalid(e.what());
    }
    const RunConfig config = s.project.config();
    StderrProgress progress(o.quiet, config);
    const Stopwatch pass_wall;  // each pass's summary times that pass
    Results results = analyse(config, s.model, progress);
    code = write_results(s.project, config, s.model, results, pass_dir, stamp, o, pass_wall, progress);
    if (code != 0 || !results.status.ok()) {
      ended = {results.status.ok() ? Status::error : results.status.status, Reason::none,
               "pass " + std::to_string(k + 1) + " (" + pass_folder(k) + "/summary.json): " + results.status.message};
      break;
    }
    try {
      schedule.finish(k, s.model, results);
    } catch (const AnalysisError& e) {
      ended = {Status::error, Reason::none, "pass " + std::to_string(k + 1) + ": " + e.what()};
      code = exit_code(Status::error);
    }
  }
  try {
    write_schedule(dir, schedule, ended, stamp, project.name(), wall.seconds());
  } catch (const WriteError& e) {
    return invalid("cannot write the schedule's results into " + dir.string() + ": " + e.what());
  }
  if (!o.quiet)
    std::fprintf(stderr, "rollsim: schedule %s: %zu of %zu passes; %s/schedule.csv\n", to_string(ended.status),
                 schedule.records().size(), schedule.passes(), dir.string().c_str());
  return code;
}

}  // namespace rollsim::app
