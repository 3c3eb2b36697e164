// The run's configuration read from a validated project: solver.cg_tolerance left unset follows Newton's tolerance
// (two orders below it) under a Newton analysis, and is 1e-4 in a linear one; a value the user gives is kept. The
// paper's pass, with the interface solved to the old default 1e-4, diverged after 0.12 mm; unset, it rolls.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../../common/PassRun.h"
#include "../../common/RollingPass.h"
#include "project/Project.h"

namespace test_run_config {

using namespace rollsim;

namespace {
RunConfig config_of(const json& j) { return parse_project(j.dump(), "p.json").config(); }

json mixed_pass() {
  json pass = testing_support::paper_pass_2d(4.0, 1.0);
  pass["solver"] = {{"mode", "mixed"}, {"update", "selective"}};
  return pass;
}
}  // namespace

TEST(RunConfig, InterfaceToleranceFollowsNewtonsUnlessGiven) {
  json pass = mixed_pass();
  EXPECT_EQ(config_of(pass).analysis, "newton");
  EXPECT_DOUBLE_EQ(config_of(pass).solver.cg_tolerance, 1e-10);
  pass["analysis"] = {{"tolerance", 1e-6}};
  EXPECT_DOUBLE_EQ(config_of(pass).solver.cg_tolerance, 1e-8);
  pass["solver"]["cg_tolerance"] = 1e-4;  // the user's value is kept
  EXPECT_DOUBLE_EQ(config_of(pass).solver.cg_tolerance, 1e-4);
  std::ifstream sample(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / "plate-hole-2d.json");
  const json unset = json::parse(sample);  // a linear project, cg_tolerance unset
  ASSERT_EQ(config_of(unset).analysis, "linear");
  EXPECT_DOUBLE_EQ(config_of(unset).solver.cg_tolerance, 1e-4);
  EXPECT_EQ(to_json(config_of(pass))["solver"]["cg_tolerance"], 1e-4);  // summary.json echoes the value used
}

TEST(RunConfig, APassWithItsInterfaceToleranceUnsetRolls) {
  const testing_support::PassRun r = testing_support::run_pass(mixed_pass());
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  ASSERT_FALSE(r.increments.empty());
  EXPECT_DOUBLE_EQ(r.increments.back().load_factor, 1.0);  // the whole 4 mm of travel
}

}  // namespace test_run_config
