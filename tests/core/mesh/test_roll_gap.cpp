// The roll polygon's lower side and the pre-bitten slab's cut: on the circle at the polygon's nodes, inside it by at
// most the chord's sagitta between them, nothing beyond the roll; a cut through the whole thickness is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "mesh/RollGap.h"
#include "mesh/StructuredBlock.h"

namespace test_roll_gap {

using namespace rollsim;

TEST(RollGap, LowerSurfaceIsThePolygonOfTheRollMesh) {
  const RollPolygon roll{0.0, 343.4, 300.0, 120};
  for (int k = 85; k <= 95; ++k) {  // nodes every 3°, around the lowest point (270°)
    const double a = k * 3.0 * M_PI / 180.0;
    EXPECT_NEAR(roll.lower_surface(300 * std::cos(a)), 343.4 + 300 * std::sin(a), 1e-9) << k;
  }
  const double sagitta = 300 * (1 - std::cos(M_PI / 120));
  for (double x = -60; x <= 60; x += 0.7) {
    const double circle = 343.4 - std::sqrt(300 * 300 - x * x), polygon = roll.lower_surface(x);
    EXPECT_GE(polygon, circle - 1e-9) << x;           // chords pass above the circle's lower side
    EXPECT_LE(polygon, circle + 1.1 * sagitta) << x;  // the sagitta is radial; vertically ≤ 1/cos(12°) of it
  }
  EXPECT_TRUE(std::isinf(roll.lower_surface(301.0)));
}

TEST(RollGap, CutScalesTheThicknessUnderTheRollOnly) {
  BlockSpec s;
  s.n = {10, 4, 1};
  s.size = {100.0, 50.0, 1.0};
  s.origin = {-100.0, 0.0, 0.0};
  Mesh slab = make_block(s);
  const Mesh before = slab;
  const RollPolygon roll{0.0, 343.4, 300.0, 120};
  cut_to_roll(slab, 1, 50.0, roll);
  for (size_t n = 0; n < slab.nodes.size(); ++n) {
    const double x = slab.nodes[n][0], surface = roll.lower_surface(x);
    EXPECT_EQ(x, before.nodes[n][0]);
    if (surface >= 50.0)
      EXPECT_EQ(slab.nodes[n][1], before.nodes[n][1]) << n;  // behind the bite: untouched
    else
      EXPECT_NEAR(slab.nodes[n][1], before.nodes[n][1] * surface / 50.0, 1e-12) << n;  // top node on the polygon
  }
  Mesh thin = make_block(s);
  EXPECT_THROW(cut_to_roll(thin, 1, 50.0, RollPolygon{0.0, 300.0, 300.0, 120}), std::invalid_argument);
}

}  // namespace test_roll_gap
