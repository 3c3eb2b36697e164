// Tests of the DGEMM probe: it times what it says (calls, order, a rate no lower than 2 n³ flops per call over its
// whole cost allows) and stops at its budget.
#include <gtest/gtest.h>

#include "base/DgemmPeak.h"

namespace rollsim::test_dgemm_peak {
namespace {

TEST(DgemmPeak, MeasuresARateAndItsCost) {
  const DgemmPeak p = measure_dgemm_peak(1, 64, 5, 10.0);
  EXPECT_EQ(p.n, 64);
  EXPECT_EQ(p.calls, 5);
  EXPECT_GT(p.gflops, 0);
  // the best of the 5 timed calls took at most their mean, itself at most the probe's total over 5
  EXPECT_GE(p.gflops, 5 * 2.0 * 64 * 64 * 64 / p.seconds / 1e9);
  EXPECT_EQ(measure_dgemm_peak(2, 0, 1, 10.0).n, 384);
  EXPECT_EQ(measure_dgemm_peak(1, 0, 1, 10.0).n, 256);
}

TEST(DgemmPeak, StopsAtItsBudget) {
  const DgemmPeak p = measure_dgemm_peak(1, 128, 1000000, 0.0);
  EXPECT_EQ(p.calls, 1);  // one timed call is always made
}

TEST(DgemmPeak, Gflops) {
  EXPECT_DOUBLE_EQ(gflops(3e9, 1.5), 2.0);
  EXPECT_DOUBLE_EQ(gflops(3e9, 0), 0.0);
}

}  // namespace
}  // namespace rollsim::test_dgemm_peak
