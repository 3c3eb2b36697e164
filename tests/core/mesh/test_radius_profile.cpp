// A radius profile: linear between its points, constant beyond the first and the last, 0 without points; its lowest
// change is the smallest of its points'.
#include <gtest/gtest.h>

#include "mesh/RadiusProfile.h"

namespace rollsim::test_radius_profile {

TEST(RadiusProfile, LinearBetweenPointsAndConstantBeyond) {
  const RadiusProfile groove{{{10.0, 0.0}, {20.0, -2.0}, {40.0, 0.0}}};
  EXPECT_DOUBLE_EQ(groove.at(0.0), 0.0);
  EXPECT_DOUBLE_EQ(groove.at(15.0), -1.0);
  EXPECT_DOUBLE_EQ(groove.at(20.0), -2.0);
  EXPECT_DOUBLE_EQ(groove.at(35.0), -0.5);
  EXPECT_DOUBLE_EQ(groove.at(100.0), 0.0);
  EXPECT_DOUBLE_EQ(groove.lowest(), -2.0);
  const RadiusProfile none;
  EXPECT_DOUBLE_EQ(none.at(5.0), 0.0);
  EXPECT_DOUBLE_EQ(none.lowest(), 0.0);
}

}  // namespace rollsim::test_radius_profile
