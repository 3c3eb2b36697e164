#pragma once
// Batch front end: each subcommand of `rollsim` is one function returning the exit code
// (0 success, 1 internal failure, 2 invalid input).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "project/Project.h"

namespace rollsim::app {

struct RunOptions {
  std::string project;
  std::optional<std::string> out;
  Overrides overrides;  // the schema's flags (--solver, --threads, …), --set PATH=VALUE and --partition
  bool quiet = false;
  std::string command;  // the command line as typed (summary.json's run.command)
};

struct BenchOptions {
  std::vector<std::string> samples;
  int repeat = 3;
  int threads = 1;
  std::string csv;
};

/// `rollsim gui [PROJECT] [--screenshot FILE.png] [--size WxH] [--run] [--partitions] [--color-by FIELD]`, and
/// `rollsim` with no arguments.
struct GuiOptions {
  std::string project;      // empty: the default project
  std::string screenshot;   // non-empty: render, save the whole window as PNG, exit
  std::string size;         // "WxH" window size
  bool run = false;         // run the analysis first (with --screenshot: results and residual plot in the image)
  bool partitions = false;  // show the partition panel and colour by subdomain
  std::string color_by;     // a result field to colour the view by after the run
  int argc = 0;             // for QApplication
  char** argv = nullptr;
};

int run_command(const RunOptions& options);
int gui_command(GuiOptions options);
/// The batch binary of a build with the window: this process becomes rollsim-gui beside it with the same arguments
/// (the window's commands and `bench accuracy`'s Qt plots live there); returns 2 with a message when it cannot.
int hand_over_to_window(int argc, char** argv);
int bench_command(const BenchOptions& options);
int export_ccx_command(const std::string& project, const std::string& out);
int check_command(const std::string& project);
/// `rollsim mesh PROJECT [--out DIR] [--partition SPEC]`: the model's meshes as DIR/mesh.vtu, without solving.
int mesh_command(const RunOptions& options);
int schema_command();

/// Where a run's (or mesh's) files go: --out, else output.dir, else results/<project name>.
std::filesystem::path output_dir(const Project& project, const RunOptions& options);

}  // namespace rollsim::app
