#pragma once
// Batch front end: each subcommand of `rollsim` is one function returning the exit code
// (0 success, 1 internal failure, 2 invalid input).
#include <optional>
#include <string>

namespace rollsim::app {

struct RunOptions {
  std::string project;
  std::optional<std::string> solver;
  std::optional<std::string> out;
  std::optional<int> threads;
  bool quiet = false;
};

int run_command(const RunOptions& options);
int check_command(const std::string& project);
int schema_command();

}  // namespace rollsim::app
