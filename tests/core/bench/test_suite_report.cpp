// The time–error Pareto front and the CSV of judged cases, on hand-made results.
#include <gtest/gtest.h>

#include <sstream>

#include "bench/SuiteReport.h"

namespace test_suite_report {

using namespace rollsim::bench;

namespace {

CaseResult result(const std::string& family, const std::string& mode, double time, double error) {
  CaseResult r;
  r.c.suite = "accuracy", r.c.family = family, r.c.variant = "h=1, \"coarse\"", r.c.mode = mode;
  r.o.status = "converged", r.o.wall_s = time, r.o.value = 1 + error;
  r.reference = 1, r.error = error, r.verdict = Verdict::ok, r.words = "measured";
  return r;
}

}  // namespace

TEST(SuiteReport, ParetoFrontKeepsRunsNoOtherBeatsInTimeAndError) {
  std::vector<CaseResult> r = {result("a", "direct", 1.0, 1e-3), result("a", "feti", 0.5, 1e-2),
                               result("a", "skyline", 2.0, 1e-2),  // slower and less accurate than direct
                               result("a", "mixed", 1.0, 1e-3),    // ties with direct: both stay
                               result("b", "direct", 9.0, 1.0)};   // its own family's only run
  r.push_back(result("a", "failed", 0.1, 1e-9));
  r.back().o.status = "not_converged";  // a run that did not converge is never on the front
  const std::vector<bool> front = pareto_front(r);
  EXPECT_EQ(front, (std::vector<bool>{true, true, false, true, true, false}));
}

TEST(SuiteReport, CsvHasOneRowPerCaseWithEveryColumnAndQuotesText) {
  std::vector<CaseResult> r = {result("a", "direct", 1.0, 1e-3), result("a", "feti", 0.5, 1e-2)};
  r[1].o.status = "not_converged", r[1].words = "CG, iteration limit";
  const std::string csv = suite_csv(r, {true, false});
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  const auto columns = [](const std::string& s) {
    int n = 1;
    bool quoted = false;
    for (char ch : s) {
      if (ch == '"') quoted = !quoted;
      if (ch == ',' && !quoted) ++n;
    }
    return n;
  };
  int rows = 0;
  while (std::getline(in, line)) {
    EXPECT_EQ(columns(line), columns(header)) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 2);
  EXPECT_NE(csv.find("\"h=1, \"\"coarse\"\"\""), std::string::npos) << "text with commas and quotes is quoted";
  EXPECT_NE(csv.find("\"CG, iteration limit\""), std::string::npos);
}

TEST(SuiteReport, StabilityTableCountsVerdictsPerFamily) {
  std::vector<CaseResult> r = {result("gap", "direct", 1, 0), result("gap", "mixed", 1, 0.5)};
  r[1].verdict = Verdict::wrong;
  const std::string md = stability_markdown(r);
  EXPECT_NE(md.find("| gap | 1 | 1 | 0 | 0 |"), std::string::npos) << md;
}

}  // namespace test_suite_report
