// A tiny instance of each benchmark suite, run as `rollsim bench` runs it (each case in its own process): every
// case is judged, none is broken (crash, NaN), every converged case has finite numbers, and the accuracy
// suite's errors stay within what its coarsest meshes allow. No timings are asserted.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "bench/Suites.h"

namespace test_suites {

using namespace rollsim::bench;

namespace {

std::vector<CaseResult> run_tiny(const std::string& suite) {
  return run_suite(suite_cases(suite, SuiteSize::tiny), 60, nullptr);
}

void expect_complete(const std::vector<CaseResult>& results) {
  ASSERT_FALSE(results.empty());
  for (const CaseResult& r : results) {
    SCOPED_TRACE(r.c.name());
    EXPECT_NE(r.verdict, Verdict::broken) << r.words;
    EXPECT_FALSE(r.words.empty());
    EXPECT_TRUE(std::isfinite(r.o.peak_rss_mb) && r.o.peak_rss_mb > 0);
    if (r.o.status != "converged") continue;
    EXPECT_TRUE(std::isfinite(r.o.wall_s) && r.o.wall_s >= 0);
    EXPECT_TRUE(std::isfinite(r.o.value));
    EXPECT_GT(r.o.dofs, 0);
    if (!r.c.reference_only) EXPECT_TRUE(std::isfinite(r.error)) << "a converged case is compared with its reference";
    if (r.c.compare_to_direct) EXPECT_TRUE(std::isfinite(r.o.solver_error));
  }
}

}  // namespace

TEST(BenchSuites, TinyAccuracySuiteIsCompleteAndFinite) {
  const auto results = run_tiny("accuracy");
  expect_complete(results);
  std::set<std::string> families, modes;
  for (const CaseResult& r : results) {
    families.insert(r.c.family), modes.insert(r.c.mode);
    EXPECT_EQ(r.o.status, "converged") << r.c.name() << ": " << r.words;
    if (!r.c.reference_only) EXPECT_LT(r.error, 0.5) << r.c.name() << " is near its reference";
  }
  EXPECT_EQ(families, (std::set<std::string>{"cantilever", "kirsch", "hertz"}));
  for (const char* m : {"skyline", "direct", "mixed", "feti-none", "feti-lumped", "feti-dirichlet"})
    EXPECT_TRUE(modes.count(m)) << m;
}

TEST(BenchSuites, TinyStabilitySuiteJudgesEveryCase) {
  const auto results = run_tiny("stability");
  expect_complete(results);
  std::set<std::string> families;
  for (const CaseResult& r : results) families.insert(r.c.family);
  EXPECT_EQ(families, (std::set<std::string>{"stiffness-ratio", "poisson", "aspect-ratio", "floating", "support-touch",
                                             "grazing", "gap", "distorted", "cg-tolerance"}));
}

TEST(BenchSuites, UnknownSuiteSizeOrFamilyIsRefusedByName) {
  EXPECT_THROW(suite_cases("speed", SuiteSize::tiny), std::invalid_argument);
  EXPECT_THROW(suite_size("huge"), std::invalid_argument);
  try {
    suite_cases("stability", SuiteSize::tiny, "nope");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("poisson"), std::string::npos) << "the choices are named: " << e.what();
  }
}

}  // namespace test_suites
