// The closed forms of the paper's plane-strain pass (100 → 86.8 mm, R 300 mm, σ_0 100 MPa, roll E 210 GPa): Sims's
// roll force 6.78 MN/m, torque per roll 213 kN·m/m and forward slip 2.5 % (the figures the rolling issue quotes),
// bite angle 12.04°, L = √(R Δh) = 62.9 mm, Hitchcock's flattening about 1 %; the friction hill above Sims; a
// rigid roll does not flatten, and a 3D pass scales with its width.
#include <gtest/gtest.h>

#include <cmath>

#include "process/rolling/RollingTheory.h"

namespace test_rolling_theory {

using namespace rollsim;

namespace {
RollingPass paper_pass() {
  RollingPass p;
  p.radius = 300, p.entry_thickness = 100, p.exit_thickness = 86.8, p.flow_stress = 100;
  p.roll_E = 210000, p.roll_nu = 0.3;
  return p;
}
}  // namespace

TEST(RollingTheory, PaperPassMatchesSimsFigures) {
  const RollingTheory t = rolling_theory(paper_pass());
  EXPECT_NEAR(t.bite_angle * 180 / M_PI, 12.04, 0.01);
  EXPECT_NEAR(t.contact_length, 62.93, 0.01);
  EXPECT_NEAR(t.sims_force, 6780, 10);     // N/mm = kN/m: 6.78 MN/m
  EXPECT_NEAR(t.sims_torque, 213e3, 1e3);  // N·mm/mm = N·m/m: 213 kN·m/m
  EXPECT_NEAR(t.sims_forward_slip, 0.025, 0.001);
  EXPECT_GT(t.neutral_angle, 0);
  EXPECT_LT(t.neutral_angle, t.bite_angle / 2);  // the neutral point lies between the exit and mid-arc
  EXPECT_GT(t.friction_hill_force, t.sims_force);
  EXPECT_LT(t.friction_hill_force, 1.3 * t.sims_force);
  EXPECT_NEAR(t.hitchcock_radius_ratio, 1.011, 0.002);
}

TEST(RollingTheory, RigidRollDoesNotFlattenAndWidthScales3D) {
  RollingPass p = paper_pass();
  p.roll_E = 0;
  EXPECT_EQ(rolling_theory(p).hitchcock_radius_ratio, 1.0);
  RollingPass wide = paper_pass();
  wide.width_axis = 1, wide.width = 350;
  EXPECT_NEAR(rolling_theory(wide).sims_force, 350 * rolling_theory(paper_pass()).sims_force, 1e-6);
  EXPECT_NEAR(rolling_theory(wide).sims_forward_slip, rolling_theory(paper_pass()).sims_forward_slip, 1e-15);
  // Wusatowski's spread of the paper's 350 mm wide slab: W = 0.0229, 1.14 mm (the issue: 0.5–1.1 mm with Sparling's)
  EXPECT_NEAR(rolling_theory(wide).wusatowski_spread, 1.1366, 1e-3);
  EXPECT_EQ(rolling_theory(paper_pass()).wusatowski_spread, 0.0);  // plane strain: no spread
}

}  // namespace test_rolling_theory
