#pragma once
// Batch front end: each subcommand of `rollsim` is one function returning the exit code
// (0 success, 1 internal failure, 2 invalid input).
#include <optional>
#include <string>
#include <vector>

namespace rollsim::app {

struct RunOptions {
  std::string project;
  std::optional<std::string> solver;
  std::optional<std::string> out;
  std::optional<int> threads;
  bool quiet = false;
};

struct BenchOptions {
  std::vector<std::string> samples;
  int repeat = 3;
  int threads = 1;
  std::string csv;
};

int run_command(const RunOptions& options);
int bench_command(const BenchOptions& options);
int export_ccx_command(const std::string& project, const std::string& out);
int check_command(const std::string& project);
int schema_command();

}  // namespace rollsim::app
