#pragma once
// The output folder of one `rollsim run`, owned by it from before the analysis until its summary is written:
// - a lock (flock on the folder itself: no lock file, and the kernel releases it however the run ends, kill -9
//   included): a second run into the same folder is refused, naming the run that owns it;
// - the earlier run's outputs are removed at the start (OutputFolder), so no result of another run is ever left
//   beside this run's summary, whatever happens to this run;
// - summary.json is written at once with `"status": "running"` and the run's stamp (start time, command, project
//   file and its SHA-256, pid, host): a folder whose run died says so, and every summary says which run made it.
// Writing that first summary is also the check that the folder can be written, before any work; check_free_space
// compares the file system's free space with an estimate of the results. Failures throw FolderError (exit 2).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollsim {

struct FolderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Which run made a folder's results: summary.json's `run`.
struct RunStamp {
  std::string command;             // the command line, as typed
  std::string project_file;        // as given
  nlohmann::json to_json() const;  // + started (UTC, ISO 8601), project_sha256, pid, host
};

/// Hex SHA-256 of a file's bytes (what `sha256sum` prints); empty if it cannot be read.
std::string file_sha256(const std::filesystem::path& file);

/// The current time in UTC, ISO 8601 to the second ("2026-11-28T11:30:26Z").
std::string utc_now();

class RunFolder {
 public:
  /// Takes `dir` for this run (creating it): the lock, the earlier outputs removed (`outputs`: the process's file
  /// names, as clear_run_outputs), summary.json `running` with `run` (RunStamp::to_json()).
  RunFolder(const std::filesystem::path& dir, const nlohmann::json& run, const std::vector<std::string>& outputs);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

 private:
  int fd_ = -1;  // the locked folder
};

/// Throws FolderError when the file system of `dir` has less free space than `bytes` (what the results need).
void check_free_space(const std::filesystem::path& dir, double bytes);

}  // namespace rollsim
