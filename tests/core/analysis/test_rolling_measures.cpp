// Steady state of a pass from its history: the means of force and torque over the last two windows of travel agree
// within 2 %. A rise that has not settled, a history shorter than two windows, or torque still moving is not steady;
// a force that steps up and down as nodes enter the arc (a finite mesh) is steady once its means settle.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/RollingMeasures.h"

using namespace rollsim;

namespace {
/// Increments every 2 mm of travel whose force and torque approach their steady values as 1 − exp(−travel / 15),
/// with an optional ripple of relative amplitude `ripple` and period 24 mm on both.
std::vector<RollingIncrement> history(int n, double torque_drift = 0, double ripple = 0) {
  std::vector<RollingIncrement> h;
  for (int i = 1; i <= n; ++i) {
    RollingIncrement r;
    r.travel = 2.0 * i;
    const double wave = 1 + ripple * std::sin(2 * M_PI * r.travel / 24);
    r.roll_force = 7000 * (1 - std::exp(-r.travel / 15)) * wave;
    r.roll_torque = (2.5e5 * (1 - std::exp(-r.travel / 15)) + torque_drift * r.travel) * wave;
    h.push_back(r);
  }
  return h;
}

/// The plain mean of the force of the increments with travel in (a, b] (equal steps: equal weights).
double force_mean(const std::vector<RollingIncrement>& h, double a, double b) {
  double s = 0;
  int n = 0;
  for (const RollingIncrement& r : h)
    if (r.travel > a && r.travel <= b) s += r.roll_force, ++n;
  return s / n;
}
}  // namespace

TEST(RollingMeasures, SteadyOnceTheMeansOverTwoWindowsAgree) {
  const double window = 31.45;  // half √(R Δh) of the paper's pass
  const auto h = history(80);
  const int steady = steady_state_from(h, window);
  ASSERT_GT(steady, 0);
  const auto settled = [&](double t) {
    const double last = force_mean(h, t - window, t), before = force_mean(h, t - 2 * window, t - window);
    return std::abs(last - before) <= 0.02 * last;
  };
  const double t = h[static_cast<size_t>(steady - 1)].travel;
  EXPECT_TRUE(settled(t));
  EXPECT_FALSE(settled(t - 2)) << "the increment before has not settled";
  const RollingIncrement m = window_mean(h, t - window, h.back().travel);
  EXPECT_NEAR(m.roll_force, force_mean(h, t - window, h.back().travel), 1e-9 * 7000);
  EXPECT_EQ(m.travel, h.back().travel);
}

TEST(RollingMeasures, ForceSteppingAsNodesEnterTheArcIsSteadyInTheMean) {
  const auto h = history(80, 0, 0.07);  // ±7 %, as the force of the 36 × 6 pass
  const int steady = steady_state_from(h, 24.0);
  ASSERT_GT(steady, 0) << "values never stay within 2 %, their means over a period do";
  const RollingIncrement m = window_mean(h, h[static_cast<size_t>(steady - 1)].travel - 24, 160);
  EXPECT_NEAR(m.roll_force, 7000, 0.02 * 7000);
}

TEST(RollingMeasures, WindowMeanWeighsEachIncrementByItsTravel) {
  std::vector<RollingIncrement> h(3);
  h[0].travel = 1, h[0].roll_force = 100;     // 1 mm
  h[1].travel = 1.01, h[1].roll_force = 1e6;  // a cut-back step of 0.01 mm
  h[2].travel = 2, h[2].roll_force = 300;     // 0.99 mm
  EXPECT_NEAR(window_mean(h, 0, 2).roll_force, (100 * 1 + 1e6 * 0.01 + 300 * 0.99) / 2, 1e-9);
  EXPECT_EQ(window_mean(h, 5, 6).roll_force, 0.0);  // nothing in the window
}

TEST(RollingMeasures, NotSteadyWhileRisingShorterThanTwoWindowsOrTorqueDrifting) {
  EXPECT_EQ(steady_state_from(history(20), 15.0), 0);           // 40 mm of travel: still rising by more than 2 %
  EXPECT_EQ(steady_state_from(history(30), 31.45), 0);          // 60 mm of travel, shorter than two windows
  EXPECT_EQ(steady_state_from(history(80, 2000.0), 31.45), 0);  // torque keeps growing by 2000 N·mm per mm
  EXPECT_EQ(steady_state_from({}, 31.45), 0);
}
