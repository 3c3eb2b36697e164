// `rollsim gui …` and `rollsim` with no arguments in the batch binary: the window lives in rollsim-gui beside it (the
// same commands, linked with Qt and VTK's rendering), which this process becomes — so that a batch run never maps
// those libraries (they were 20 ms of every run's start, a sixth of the 2D square's whole run).
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "Commands.h"
#include "base/ModuleLoader.h"

namespace rollsim::app {

int hand_over_to_window(int argc, char** argv) {
  std::string path = module_path("ROLLSIM_GUI", "rollsim-gui").string();
  std::vector<char*> args(argv, argv + argc);
  args[0] = path.data();
  args.push_back(nullptr);
  execv(path.c_str(), args.data());
  std::cerr << "rollsim: error: the window is rollsim-gui beside rollsim, which cannot be started (" << path << ": "
            << std::strerror(errno) << "); this build may have none (configured with -DROLLSIM_BUILD_GUI=OFF)\n";
  return 2;
}

int gui_command(GuiOptions o) { return hand_over_to_window(o.argc, o.argv); }

}  // namespace rollsim::app
