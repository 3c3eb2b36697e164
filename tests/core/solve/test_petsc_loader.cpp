// The `petsc` strategy is loaded, not linked: with PETSc in the build the module is looked for beside the running
// executable or at $ROLLSIM_PETSC_MODULE, and a module that cannot be loaded is an std::invalid_argument naming the
// file and the loader's reason — never a crash; nothing is loaded (and the rank is 0) until `petsc` is asked for.
// Without PETSc the strategy is refused saying how to build it. (Loading the real module: tests/app/test_petsc_run.)
#include <gtest/gtest.h>
#include <stdlib.h>

#include <string>

#include "project/Project.h"
#include "solve/PetscModule.h"
#include "solve/PetscStrategy.h"
#include "solve/SolverStrategy.h"

namespace test_petsc_loader {

using namespace rollsim;

namespace {

/// The message of the std::invalid_argument that make_solver("petsc") throws ("" when it does not throw).
std::string refusal(const SolverOptions& options = {}) {
  try {
    make_solver("petsc", options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

#ifdef ROLLSIM_HAVE_PETSC

/// Sets an environment variable for its scope (unset again after).
struct ScopedEnv {
  ScopedEnv(const char* name, const std::string& value) : name_(name) { setenv(name, value.c_str(), 1); }
  ~ScopedEnv() { unsetenv(name_); }
  const char* name_;
};

TEST(PetscLoader, LooksBesideTheExecutableUnlessTheEnvironmentNamesAPath) {
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe");
  EXPECT_EQ(petsc_module_path(), exe.parent_path() / "rollsim_petsc.so");
  const ScopedEnv env(kPetscModuleEnv, "/elsewhere/my_petsc.so");
  EXPECT_EQ(petsc_module_path(), std::filesystem::path("/elsewhere/my_petsc.so"));
}

TEST(PetscLoader, AMissingModuleIsRefusedNamingTheFileAndTheReason) {
  const ScopedEnv env(kPetscModuleEnv, "/nonexistent/rollsim_petsc.so");
  const std::string message = refusal();
  EXPECT_NE(message.find("cannot load its module /nonexistent/rollsim_petsc.so"), std::string::npos) << message;
  EXPECT_NE(message.find("No such file"), std::string::npos) << message;  // dlerror()'s words
  EXPECT_EQ(process_rank(), 0) << "nothing loaded, nothing started";
}

TEST(PetscLoader, ALibraryWithoutTheEntryPointIsRefused) {
  const ScopedEnv env(kPetscModuleEnv, "libm.so.6");
  const std::string message = refusal();
  EXPECT_NE(message.find("no entry point rollsim_petsc_module"), std::string::npos) << message;
}

TEST(PetscLoader, AnUnknownMethodIsRefusedBeforeAnythingIsLoaded) {  // by the project's validation: an enum after it
  const ScopedEnv env(kPetscModuleEnv, "/nonexistent/rollsim_petsc.so");
  try {
    parse_project(R"({"dimension": 2, "solver": {"mode": "petsc", "petsc_method": "gamg"}})", "p");
    FAIL() << "gamg accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(
        std::string(e.what()).find("solver.petsc_method: must be one of bddc, fetidp, mumps, mixed, got \"gamg\""),
        std::string::npos)
        << e.what();
  }
}
#else
TEST(PetscLoader, ABuildWithoutPetscRefusesTheStrategy) {
  EXPECT_FALSE(petsc_available());
  EXPECT_NE(refusal().find("ROLLSIM_WITH_PETSC"), std::string::npos);
  EXPECT_EQ(process_rank(), 0);
}
#endif

}  // namespace

}  // namespace test_petsc_loader
