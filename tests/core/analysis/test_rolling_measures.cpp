// Steady state of a pass from its history: force and torque settle to within 2 % over one contact length of travel;
// a rise that has not settled, a history shorter than the window, or torque still moving is not steady.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/RollingMeasures.h"

using namespace rollsim;

namespace {
/// Increments every 2 mm of travel whose force and torque approach their steady values as 1 − exp(−travel / 15).
std::vector<RollingIncrement> history(int n, double torque_drift = 0) {
  std::vector<RollingIncrement> h;
  for (int i = 1; i <= n; ++i) {
    RollingIncrement r;
    r.travel = 2.0 * i;
    r.roll_force = 7000 * (1 - std::exp(-r.travel / 15));
    r.roll_torque = 2.5e5 * (1 - std::exp(-r.travel / 15)) + torque_drift * r.travel;
    h.push_back(r);
  }
  return h;
}
}  // namespace

TEST(RollingMeasures, SteadyOnceForceAndTorqueSettleOverOneContactLength) {
  const double window = 62.9;  // √(R Δh) of the paper's pass
  const auto h = history(80);
  const int steady = steady_state_from(h, window);
  ASSERT_GT(steady, 0);
  // the first increment whose preceding 62.9 mm stay within 2 %: 1 − exp(−(t − 62.9)/15) ≥ 0.98 (1 − exp(−t/15))
  const double t = h[static_cast<size_t>(steady - 1)].travel;
  EXPECT_GE(std::exp(-(t - window) / 15) - 0.98 * std::exp(-t / 15), 0.0 - 1e-12);
  EXPECT_LE(std::exp(-(t - window) / 15), 0.02 + 1e-3);
  const double before = t - 2;  // the increment before is not yet settled
  EXPECT_GT(1 - (1 - std::exp(-(before - window) / 15)) / (1 - std::exp(-before / 15)), 0.02);
}

TEST(RollingMeasures, NotSteadyWhileRisingShorterThanTheWindowOrTorqueDrifting) {
  EXPECT_EQ(steady_state_from(history(20), 62.9), 0);          // 40 mm of travel: still rising by more than 2 %
  EXPECT_EQ(steady_state_from(history(30), 100.0), 0);         // 60 mm of travel, shorter than the window
  EXPECT_EQ(steady_state_from(history(80, 2000.0), 62.9), 0);  // torque keeps growing by 2000 N·mm per mm
  EXPECT_EQ(steady_state_from({}, 62.9), 0);
}
