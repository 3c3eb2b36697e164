// Steady state of a pass from its history: the means of force and torque over the last two windows of travel agree
// within 2 %. A rise that has not settled, a history shorter than two windows, or torque still moving is not steady;
// a force that steps up and down as nodes enter the arc (a finite mesh) is steady once its means settle; with the
// shape (an ALE pass in 3D) a mean spread still growing is not steady.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/Results.h"
#include "process/rolling/RollingMeasures.h"
#include "process/rolling/RollingProcess.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_rolling_measures {

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

/// An increment of model `m` (3D) with every body at rest: its fields for a test to set.
IncrementResults at_rest(const Model& m) {
  IncrementResults inc;
  for (const Body& b : m.bodies) {
    BodyResults r;
    r.displacement = Eigen::VectorXd::Zero(b.mesh.num_nodes() * 3);
    r.nodal_force = Eigen::VectorXd::Zero(b.mesh.num_nodes() * 3);
    inc.bodies.push_back(r);
  }
  return inc;
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

TEST(RollingMeasures, WithTheShapeNotSteadyWhileTheMeanSpreadStillGrows) {
  std::vector<RollingIncrement> growing = history(80), settled = history(80);
  for (size_t i = 0; i < growing.size(); ++i) {
    growing[i].mean_spread = 0.01 * growing[i].travel;  // 0.3 mm more per window, as the 3D ALE window's
    settled[i].mean_spread = 1.2 * (1 - std::exp(-growing[i].travel / 15));
  }
  EXPECT_GT(steady_state_from(growing, 31.45), 0) << "force and torque alone are steady";
  EXPECT_EQ(steady_state_from(growing, 31.45, true), 0);
  EXPECT_EQ(steady_state_from(settled, 31.45, true), steady_state_from(settled, 31.45));
}

TEST(RollingMeasures, WithTheShapeAnOvershootIsNotSteadyOnItsWayDown) {
  // the spread rises to 1.55 mm at 130 mm of travel and decays to 1.30 over about 80 mm, as the 3D ALE window's: two
  // windows about the peak have equal means, yet the spread is 15 % above where it settles
  std::vector<RollingIncrement> h = history(200);
  for (RollingIncrement& r : h) {
    const double t = r.travel;
    r.mean_spread = t < 130 ? 1.55 * t / 130 : 1.30 + 0.25 * std::exp(-(t - 130) / 40);
  }
  const auto means_agree = [&](double t) {
    const double a = window_mean(h, t - 31.45, t).mean_spread, b = window_mean(h, t - 62.9, t - 31.45).mean_spread;
    return std::abs(a - b) <= 0.02 * a + 0.01;
  };
  EXPECT_TRUE(means_agree(170)) << "the means alone are fooled about the peak: the spread is 1.39 there";
  const int steady = steady_state_from(h, 31.45, true);
  ASSERT_GT(steady, 0);
  EXPECT_GT(h[static_cast<size_t>(steady - 1)].travel, 230);
  EXPECT_NEAR(h[static_cast<size_t>(steady - 1)].mean_spread, 1.30, 0.02 * 1.30 + 0.01);
  // nor before the window's first material has left it (its length: 263 mm for the 3D sample's window)
  const int flushed = steady_state_from(h, 31.45, true, 263);
  EXPECT_NEAR(h[static_cast<size_t>(flushed - 1)].travel, 264, 1e-9);
  EXPECT_EQ(steady_state_from(h, 31.45, false, 263), steady_state_from(h, 31.45)) << "the force's own rule";
}

// Spread, two ways, from the slab's side face past the exit plane: the widest point and the mean width over the
// thickness. A 3D slab moved 150 mm past the exit plane whose side leans out linearly with height (y = b0/2 + c z on
// the side face; the half thickness 50 mm behind the arc): widest 2 c · 50, mean 2 c · 25; the half-width model
// doubles both.
TEST(RollingMeasures, SpreadAtTheWidestPointAndOfTheMeanWidth) {
  const json project = {{"dimension", 3},
                        {"process",
                         {{"type", "rolling"},
                          {"slab_nx", 8},
                          {"slab_nw", 2},
                          {"slab_nt", 4},
                          {"roll_n_axial", 2},
                          {"roll_n_around", 48}}}};
  const Project p = parse_project(project.dump(), "lean");
  const Model m = build_model(p);
  const double c = 0.02;
  IncrementResults inc = at_rest(m);
  const Mesh& slab = m.bodies[0].mesh;
  for (int n = 0; n < slab.num_nodes(); ++n) {
    const auto& X = slab.nodes[static_cast<size_t>(n)];
    inc.bodies[0].displacement[3 * n] = 150;  // the columns at X in (−150, −87] lie past the exit
    inc.bodies[0].displacement[3 * n + 1] = X[1] / 175 * c * X[2];  // the side face (y = 175) leans out
  }
  Results results;
  results.increments.push_back(inc);
  const RollingResults r = measure_rolling(rolling_pass(p.data.at("process"), m), m, results);
  ASSERT_EQ(r.increments.size(), 1u);
  EXPECT_NEAR(r.increments[0].spread, 2 * c * 50, 1e-9);
  EXPECT_NEAR(r.increments[0].mean_spread, 2 * c * 25, 1e-9);
}

// An ALE window's volume balance counts each face's area: a 3D window whose material leaves 2 % thinner and as much
// wider as keeps its volume balances to round-off (a face's height times its mean advance — the first measure —
// read −2 %: it missed the spread).
TEST(RollingMeasures, AnAleWindowsFluxBalanceCountsTheExitFacesSpread) {
  const json project = {{"dimension", 3},
                        {"process",
                         {{"type", "rolling"},
                          {"formulation", "ale"},
                          {"slab_nx", 8},
                          {"slab_nw", 2},
                          {"slab_nt", 2},
                          {"roll_n_axial", 2},
                          {"roll_n_around", 48}}}};
  const Project p = parse_project(project.dump(), "window");
  const Model m = build_model(p);
  const RollingPass pass = rolling_pass(p.data.at("process"), m);
  IncrementResults inc = at_rest(m);
  const Mesh& slab = m.bodies[static_cast<size_t>(pass.slab)].mesh;
  double entry = 0, exit = 0;  // the faces' heights: the window is cut to the roll's gap at its exit
  for (int n : slab.node_sets.at("xmin")) entry = std::max(entry, slab.nodes[static_cast<size_t>(n)][2]);
  for (int n : slab.node_sets.at("xmax")) exit = std::max(exit, slab.nodes[static_cast<size_t>(n)][2]);
  const double thinner = 0.02, wider = 1 / (1 - thinner) - 1;
  for (int n = 0; n < slab.num_nodes(); ++n) {  // the exit face 2 % thinner and 1/0.98 wider, as fast as it is thin
    const auto& X = slab.nodes[static_cast<size_t>(n)];
    const double along = (X[0] + pass.ale_entry) / (pass.ale_entry + pass.ale_exit);  // 0 at the entry, 1 at the exit
    inc.bodies[static_cast<size_t>(pass.slab)].displacement[3 * n] = 0.5 * (1 + along * (entry / exit - 1));
    inc.bodies[static_cast<size_t>(pass.slab)].displacement[3 * n + 1] = along * wider * X[1];
    inc.bodies[static_cast<size_t>(pass.slab)].displacement[3 * n + 2] = -along * thinner * X[2];
  }
  inc.load_factor = 0.5 / pass.travel;
  Results results;
  results.increments.push_back(inc);
  const RollingResults r = measure_rolling(pass, m, results);
  ASSERT_EQ(r.increments.size(), 1u);
  EXPECT_NEAR(r.increments[0].volume_change, 0, 1e-12);
}

// A column is named for what it holds: the contact's arc length in plane strain [mm], its area in 3D [mm²] —
// rolling.csv's header and summary.json's key alike (RollingReport writes both from Measure::name).
TEST(RollingMeasures, ContactIsALengthIn2DAndAnAreaIn3D) {
  auto contact = [](int dim) {
    for (const RollingMeasure& m : rolling_measures())
      if (m.field == &RollingIncrement::contact_length) return m.in(dim);
    return Measure{};
  };
  EXPECT_EQ(contact(2).name, "contact_length");
  EXPECT_EQ(contact(2).unit, "mm");
  EXPECT_EQ(contact(3).name, "contact_area");
  EXPECT_EQ(contact(3).unit, "mm²");
  EXPECT_EQ(contact(3).label, "contact area");
}

}  // namespace test_rolling_measures
