// The batch binary and the window: `rollsim` maps no Qt or VTK rendering library (a batch run starts without them),
// and hands the window's commands over to rollsim-gui beside it — whose own messages come back — or says, exit 2,
// that it cannot start it.
#include <gtest/gtest.h>

#include <string>

#include "RunBinary.h"

namespace test_gui_hand_over {

TEST(GuiHandOver, TheBatchBinaryMapsNoWindowLibrary) {
  const RunResult r = run_program("/usr/bin/ldd", {ROLLSIM_BINARY});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_NE(r.out.find("libcholmod"), std::string::npos) << r.out;  // what a run needs is there
  EXPECT_EQ(r.out.find("libQt5"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("vtkRendering"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("vtkGUISupportQt"), std::string::npos) << r.out;
}

TEST(GuiHandOver, AWindowThatCannotStartIsSaidWithExitTwo) {
  const RunResult r = run_program("/usr/bin/env", {"ROLLSIM_GUI=/nonexistent/rollsim-gui", ROLLSIM_BINARY, "gui"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("rollsim-gui beside rollsim, which cannot be started (/nonexistent/rollsim-gui"),
            std::string::npos)
      << r.err;
}

#ifdef ROLLSIM_HAVE_GUI
TEST(GuiHandOver, TheWindowsCommandsReachRollsimGui) {
  // without a display rollsim-gui says so itself: the command got there, with its arguments
  const RunResult r = run_program("/usr/bin/env", {"-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", "-u", "QT_QPA_PLATFORM",
                                                   ROLLSIM_BINARY, "gui", "--screenshot", "/tmp/never.png"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("the window needs a display"), std::string::npos) << r.err;
}
#endif

}  // namespace test_gui_hand_over
