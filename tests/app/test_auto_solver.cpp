// `rollsim run --solver auto` (and solver.mode: auto): the run names the chosen mode and the predicted costs it was
// chosen from in its progress and in summary.json (solver.mode is the chosen one, solver.auto says why); a word that
// is not a mode is refused with exit 2, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_auto_solver {

namespace fs = std::filesystem;
using json = nlohmann::json;

TEST(AutoSolver, TheRunSaysWhichModeItChoseAndWhy) {
  const std::string dir = make_temp_dir("auto"), out = dir + "/out";
  const RunResult r = run_rollsim(
      {"run", ROLLSIM_SOURCE_DIR "/samples/block-indent-2d-50x30.json", "--solver", "auto", "--out", out}, 120);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = json::parse(read_text(out + "/summary.json"));
  const json& a = s.at("solver").at("auto");
  const std::string chosen = a.at("chosen").get<std::string>();
  EXPECT_EQ(s.at("solver").at("mode"), chosen);
  ASSERT_TRUE(a.at("predicted_flops").contains(chosen)) << a.dump();
  for (const auto& [mode, flops] : a.at("predicted_flops").items()) {
    EXPECT_TRUE(mode == "direct" || mode == "mixed" || mode == "feti") << mode;
    EXPECT_GE(flops.get<double>(), a.at("predicted_flops").at(chosen).get<double>()) << mode;
  }
  EXPECT_NE(r.err.find("solver auto: " + chosen + " (predicted cost:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("solver " + chosen + " (auto)"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(AutoSolver, WordsThatAreNoModeAreRefused) {
  const std::string dir = make_temp_dir("auto-bad"), out = dir + "/out";
  for (const char* bad : {"Auto", "automatic", "fastest"}) {
    const RunResult r =
        run_rollsim({"run", ROLLSIM_SOURCE_DIR "/samples/block-indent-2d-50x30.json", "--solver", bad, "--out", out});
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find(std::string("--solver: must be one of skyline, direct, mixed, feti, petsc, auto, got \"") +
                         bad + "\""),
              std::string::npos)
        << "the valid words include auto: " << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  fs::remove_all(dir);
}

}  // namespace test_auto_solver
