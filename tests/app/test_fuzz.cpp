// Mutated projects through the real binary: `check` and `run` exit 0, 2 or a documented not-converged code (never 1,
// a signal or a hang); a refusal says "error:"; a solved mutant leaves a converged summary.json without NaN or
// Infinity. Every run of a valid mutant writes into the same output folder, which after each holds that run only.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "../common/ProjectMutator.h"
#include "RunBinary.h"

namespace test_fuzz {

namespace {

// 300 processes of `check` (140 ms each, mostly the dynamic loader mapping Qt and VTK) and the runs: still the
// suite's longest test (94 s at 500 on 2026-11-28, with CI near its 20 minutes); the validator itself meets 20 000
// mutants in-process (ProjectFuzz)
constexpr unsigned kMutants = 300;
constexpr unsigned kRunEvery = 10;  // every 10th mutant is also run; so is every mutant that `check` accepts

void expect_clean_exit(const RunResult& r, const std::string& what) {
  ASSERT_FALSE(r.timed_out) << what;
  ASSERT_EQ(r.signal, 0) << what << "\n" << r.err;
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 2 || r.exit_code == 3 || r.exit_code == 4)
      << what << ": exit " << r.exit_code << "\n"
      << r.err;
  if (r.exit_code == 2) {
    EXPECT_NE(r.err.find("error:"), std::string::npos) << what << "\n" << r.err;
  }
}

/// nlohmann writes a NaN or an infinity as null: a summary must hold none.
bool has_null(const nlohmann::json& j) {
  if (j.is_null()) return true;
  for (const auto& v : j)
    if ((v.is_structured() || v.is_null()) && has_null(v)) return true;
  return false;
}

/// After a run: exit 0 leaves a converged summary (and maybe result.vtu); exit 2 leaves nothing or an error summary,
/// 3 / 4 a not_converged / diverged one — and no file of the previous mutant's run.
void expect_sound_output(const RunResult& r, const std::string& out, const std::string& what) {
  const std::string text = read_text(out + "/summary.json");
  if (!text.empty()) {
    EXPECT_FALSE(has_null(nlohmann::json::parse(text))) << what << ": NaN or Infinity in the summary";
  }
  for (const auto& name : list_dir(out))
    EXPECT_TRUE(name == "summary.json" || (name == "result.vtu" && r.exit_code == 0)) << what << ": " << name;
  if (r.exit_code == 0) {
    ASSERT_NE(text, "") << what;
    EXPECT_EQ(nlohmann::json::parse(text)["status"], "converged") << what;
  } else if (r.exit_code == 2 && !text.empty()) {
    EXPECT_EQ(nlohmann::json::parse(text)["status"], "error") << what;
  } else if (r.exit_code > 2) {
    EXPECT_EQ(nlohmann::json::parse(text)["status"], r.exit_code == 3 ? "not_converged" : "diverged") << what;
  }
}

}  // namespace

TEST(BinaryFuzz, MutantsExitZeroOrTwoAndNeverLeaveNaN) {
  const std::string dir = make_temp_dir("fuzz"), file = dir + "/mutant.json", out = dir + "/out";
  int valid = 0, runs = 0, solved = 0, overflowed = 0;
  for (unsigned seed = 1; seed <= kMutants; ++seed) {
    std::mt19937 rng(seed * 7919u);
    write_text(file, fuzz::mutate(fuzz::kSeeds[seed % std::size(fuzz::kSeeds)], rng));
    const std::string what = "seed " + std::to_string(seed);
    const RunResult check = run_rollsim({"check", file});
    expect_clean_exit(check, what + " (check)");
    valid += check.exit_code == 0;
    if (check.exit_code != 0 && seed % kRunEvery != 0) continue;
    // refused input writes nothing (the folder keeps the earlier run); a run of a valid project replaces it
    if (check.exit_code != 0) std::filesystem::remove_all(out);
    const RunResult run = run_rollsim({"run", file, "--out", out, "--quiet"});
    expect_clean_exit(run, what + " (run)");
    if (check.exit_code == 2) {
      EXPECT_EQ(run.exit_code, 2) << what << ": run accepted what check refused";
    }
    expect_sound_output(run, out, what + " (run)");
    ++runs;
    solved += run.exit_code == 0;
    overflowed += run.err.find("are not finite numbers") != std::string::npos;
  }
  std::printf("  %u mutants checked (%d valid), %d run (%d solved, %d refused for non-finite results)\n", kMutants,
              valid, runs, solved, overflowed);
  EXPECT_GT(solved, 0) << "no mutant was solved: the loop would not exercise the solver";
  std::filesystem::remove_all(dir);
}

}  // namespace test_fuzz
