// Tests of summary.json's factorization rate: factor_gflops = all factorizations' flops over their seconds, and its
// fraction of the DGEMM peak when the run measured one; nothing of the kind when nothing was factored.
#include <gtest/gtest.h>

#include "io/Summary.h"

namespace rollsim {
namespace {

Results factored(double flops, double seconds) {
  Results r;
  r.status = {Status::error, Reason::none, "no fields needed here"};  // the solver section without results
  r.solver.factor_flops_total = flops;
  r.timing.factorize_s = seconds;
  return r;
}

TEST(Summary, ReportsTheFactorizationRateAgainstThePeak) {
  RunInfo run{"t", "direct"};
  run.dgemm_peak_gflops = 40;
  run.peak_probe_s = 0.01;
  const auto s = make_summary(Model{}, factored(6e9, 0.5), run);
  EXPECT_DOUBLE_EQ(s["solver"]["factor_gflops"].get<double>(), 12.0);
  EXPECT_DOUBLE_EQ(s["solver"]["dgemm_peak_gflops"].get<double>(), 40.0);
  EXPECT_DOUBLE_EQ(s["solver"]["factor_peak_fraction"].get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(s["timing"]["peak_probe_s"].get<double>(), 0.01);
}

TEST(Summary, LeavesThePeakOutWhenNotMeasuredAndTheRateWhenNothingWasFactored) {
  const auto s = make_summary(Model{}, factored(6e9, 0.5), RunInfo{"t", "direct"});
  EXPECT_DOUBLE_EQ(s["solver"]["factor_gflops"].get<double>(), 12.0);
  EXPECT_FALSE(s["solver"].contains("factor_peak_fraction"));
  EXPECT_FALSE(s["timing"].contains("peak_probe_s"));
  const auto none = make_summary(Model{}, factored(0, 0), RunInfo{"t", "petsc"});
  EXPECT_FALSE(none["solver"].contains("factor_gflops"));
}

}  // namespace
}  // namespace rollsim
