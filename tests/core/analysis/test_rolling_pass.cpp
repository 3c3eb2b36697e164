// The first millimetres of the paper's plane-strain pass (100 → 86.8 mm, R 300 mm, σ_0 100 MPa, E 210 GPa, sticking
// friction capped at k, coarse 36 × 6 slab): the roll bites at once (pre-bitten entry), and its measures are those of
// a pass — roll force within the slab method's range, the lever arm of the torque a fraction of the contact length,
// the contact length and exit thickness those of the nominal geometry, the slab leaving faster than the roll.
#include <gtest/gtest.h>

#include <cmath>

#include "../../common/RunJson.h"

using namespace rollsim;
using nlohmann::json;

namespace {
json pass(double travel) {
  return {{"name", "pass"},
          {"dimension", 2},
          {"process",
           {{"type", "rolling"},
            {"slab_nx", 36},
            {"slab_nt", 6},
            {"slab_E", 210000.0},
            {"travel", travel},
            {"travel_increment", 2.0}}},
          {"solver", {{"mode", "direct"}}}};
}
}  // namespace

TEST(RollingPass, FirstMillimetresMeasureLikeAPass) {
  const Results r = testing_support::run_json(pass(4.0));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.rolling);
  const RollingResults& roll = *r.rolling;
  ASSERT_GE(roll.increments.size(), 2u);  // 2 mm steps, more where the driver cut one back
  EXPECT_EQ(roll.bite_increment, 1);
  const RollingIncrement& last = roll.increments.back();
  EXPECT_DOUBLE_EQ(last.travel, 4.0);
  // Sims 6.78 MN/m and the homogeneous slab with sticking friction 8.23 MN/m (docs: the pass is not steady yet)
  EXPECT_GT(last.roll_force, 0.7 * 6780);
  EXPECT_LT(last.roll_force, 1.3 * 8230);
  const double L = std::sqrt(300 * 13.2);  // nominal projected contact length √(R Δh)
  EXPECT_GT(last.roll_torque / last.roll_force, 0.3 * L);
  EXPECT_LT(last.roll_torque / last.roll_force, 0.8 * L);
  EXPECT_NEAR(last.contact_length, L, 0.1 * L);
  EXPECT_NEAR(last.exit_thickness, 86.8, 0.005 * 86.8);
  EXPECT_GT(last.forward_slip, 0.0);
  EXPECT_LT(last.forward_slip, 0.15);
  EXPECT_EQ(last.spread, 0.0);  // plane strain
}
