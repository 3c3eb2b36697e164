// Mutated projects through the real binary: `run` exits 0 (summary without NaN) or 2 (message),
// never a signal, an internal error (1) or a hang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../common/ProjectMutator.h"
#include "RunBinary.h"

TEST(BinaryFuzz, RunNeverCrashesOrHangs) {
  const std::string dir = make_temp_dir("fuzz");
  int ok = 0, refused = 0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    std::mt19937 rng(seed * 7919u);
    std::ofstream(dir + "/p.json") << fuzz::mutate(fuzz::kSeed, rng);
    std::filesystem::remove_all(dir + "/out");
    const RunResult r = run_rollsim({"run", dir + "/p.json", "--out", dir + "/out", "--quiet"}, 60);
    ASSERT_FALSE(r.timed_out) << "seed " << seed;
    ASSERT_EQ(r.signal, 0) << "seed " << seed << "\n" << r.err;
    ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 2) << "seed " << seed << " exit " << r.exit_code << "\n" << r.err;
    if (r.exit_code == 2) {
      ++refused;
      EXPECT_NE(r.err.find("error:"), std::string::npos) << r.err;
      continue;
    }
    ++ok;
    std::ifstream in(dir + "/out/summary.json");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(nlohmann::json::parse(text)["status"], "converged");
    EXPECT_EQ(text.find("NaN"), std::string::npos);
    EXPECT_EQ(text.find("null"), std::string::npos) << "non-finite number in summary (seed " << seed << ")";
  }
  std::printf("  200 mutants through rollsim run: %d solved, %d refused\n", ok, refused);
  EXPECT_GT(ok, 0) << "no mutant was solvable: the loop would not exercise the solver";
  std::filesystem::remove_all(dir);
}
