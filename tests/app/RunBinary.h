#pragma once
// Runs the real rollsim binary with arguments, capturing exit status, output and time; kills it after a timeout.
#include <functional>
#include <string>
#include <vector>

struct RunResult {
  int exit_code = -1;  // -1: killed by a signal or timed out
  int signal = 0;      // the terminating signal, 0 if it exited
  bool timed_out = false;
  double seconds = 0;  // wall time
  std::string out, err;
};

/// Spawns ROLLSIM_BINARY with `args` (stdin: /dev/null), waits at most `timeout_s` seconds (then SIGKILL).
RunResult run_rollsim(const std::vector<std::string>& args, int timeout_s = 60);

/// The same for another program (an absolute path), e.g. mpirun starting rollsim on several ranks.
RunResult run_program(const std::string& program, const std::vector<std::string>& args, int timeout_s = 60);

/// The same, sending SIGINT (Ctrl-C) once `marker` appears in the program's stderr (never if empty).
RunResult run_program_interrupted(const std::string& program, const std::vector<std::string>& args,
                                  const std::string& marker, int timeout_s = 60);

/// The same, calling `on_marker` (with the program's pid) once `marker` appears in its stderr: a signal of one's
/// choice, or a second run started while the first computes.
RunResult run_program_on_marker(const std::string& program, const std::vector<std::string>& args,
                                const std::string& marker, const std::function<void(int pid)>& on_marker,
                                int timeout_s = 60);

/// A fresh empty directory under the system temp dir.
std::string make_temp_dir(const std::string& tag);

/// The whole content of a file ("" if it cannot be read).
std::string read_text(const std::string& path);

/// Writes `text` to `path` (binary, truncating).
void write_text(const std::string& path, const std::string& text);

/// The names of the entries of a directory, hidden ones included (empty if it does not exist).
std::vector<std::string> list_dir(const std::string& dir);
