// `rollsim bench accuracy | stability` as a user runs it: the tiny size writes SUITE.csv and SUITE.md (and, with
// the window's libraries, one time–error plot per accuracy family); an unknown size or family is refused (exit 2);
// `rollsim bench` with neither project files nor a suite says what it needs.
#include <gtest/gtest.h>

#include <algorithm>

#include "RunBinary.h"

namespace test_bench_suites {

namespace {

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TEST(BenchSuites, AccuracyTinyWritesTableMarkdownAndPlots) {
  const std::string dir = make_temp_dir("bench-accuracy");
  const RunResult r =
      run_rollsim({"bench", "accuracy", "--size", "tiny", "--family", "cantilever", "--out", dir, "--quiet"}, 120);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto files = list_dir(dir);
  EXPECT_TRUE(has(files, "accuracy.csv"));
  EXPECT_TRUE(has(files, "accuracy.md"));
#ifdef ROLLSIM_HAVE_GUI
  EXPECT_TRUE(has(files, "accuracy-cantilever.png"));
#endif
  const std::string csv = read_text(dir + "/accuracy.csv");
  EXPECT_EQ(csv.find("nan"), std::string::npos) << csv;
  EXPECT_NE(csv.find("feti-dirichlet"), std::string::npos);
}

TEST(BenchSuites, BadSizeOrFamilyOrNothingIsRefused) {
  const std::string dir = make_temp_dir("bench-bad");
  RunResult r = run_rollsim({"bench", "stability", "--size", "huge", "--out", dir});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("tiny, quick, full"), std::string::npos) << r.err;
  r = run_rollsim({"bench", "stability", "--size", "tiny", "--family", "nope", "--out", dir});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("poisson"), std::string::npos) << r.err;
  r = run_rollsim({"bench"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("accuracy, stability"), std::string::npos) << r.err;
}

}  // namespace test_bench_suites
