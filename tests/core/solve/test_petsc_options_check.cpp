// solver.petsc_options may not make PETSc open files or start programs (solve/PetscOptionsCheck.h): the reported
// `-ksp_monitor ascii:PATH` (replaced PATH) and `-log_view :PATH` (emptied it) are refused, as are an options file,
// -info into a file and debuggers; monitors and views to the terminal and solver settings pass.
#include <gtest/gtest.h>

#include "solve/PetscOptionsCheck.h"

namespace test_petsc_options_check {

using namespace rollsim;

TEST(PetscOptionsCheck, OptionsThatOpenFilesOrStartProgramsAreRefused) {
  for (const char* bad : {"-ksp_monitor ascii:/tmp/victim", "-log_view :/tmp/victim", "-ksp_view binary:out.bin",
                          "-pc_bddc_use_faces -ksp_converged_reason ascii:log.txt:ascii_info",
                          "-options_file more.opts", "-info /tmp/info.log", "-info log:ksp",
                          "-on_error_attach_debugger", "-start_in_debugger gdb", "-viewer_binary_filename x"}) {
    const std::string problem = petsc_options_problem(bad);
    EXPECT_FALSE(problem.empty()) << bad;
    EXPECT_NE(problem.find("may not make PETSc open files"), std::string::npos) << problem;
  }
  EXPECT_NE(petsc_options_problem("-ksp_monitor ascii:/tmp/victim").find("'/tmp/victim'"), std::string::npos);
}

TEST(PetscOptionsCheck, TerminalOutputAndSettingsPass) {
  for (const char* good :
       {"", "-ksp_monitor", "-ksp_view ::ascii_info_detail", "-log_view", "-log_view ::ascii_flamegraph",
        "-pc_bddc_use_faces -ksp_rtol 1e-10", "-ksp_max_it 200 -pc_bddc_corner_selection 0", "-info :ksp",
        "-ksp_monitor_true_residual", "-mat_view ascii"})
    EXPECT_EQ(petsc_options_problem(good), "") << good;
}

}  // namespace test_petsc_options_check
