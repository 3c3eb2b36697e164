#pragma once
// Runs the real rollsim binary with arguments, capturing exit status and output; kills it after a timeout.
#include <string>
#include <vector>

struct RunResult {
  int exit_code = -1;  // -1: killed by a signal or timed out
  int signal = 0;
  bool timed_out = false;
  std::string out, err;
};

RunResult run_rollsim(const std::vector<std::string>& args, int timeout_s = 60);

/// A fresh empty directory under the system temp dir.
std::string make_temp_dir(const std::string& tag);
