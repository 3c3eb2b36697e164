// A thermal table's properties against temperature (model/ThermalTable): linear between its points, held at its end
// values beyond them.
#include <gtest/gtest.h>

#include "model/ThermalTable.h"

namespace test_thermal_table {

using namespace rollsim;

TEST(ThermalTable, IsLinearBetweenItsPointsAndHeldBeyondThem) {
  ThermalTable t;
  t.temperature = {20, 600, 1000};
  t.conductivity = {50, 35, 27};
  t.heat_capacity = {3.6, 4.8, 5.0};
  EXPECT_DOUBLE_EQ(t.conductivity_at(20), 50);
  EXPECT_DOUBLE_EQ(t.conductivity_at(310), 42.5);
  EXPECT_DOUBLE_EQ(t.conductivity_at(600), 35);
  EXPECT_DOUBLE_EQ(t.conductivity_at(800), 31);
  EXPECT_DOUBLE_EQ(t.heat_capacity_at(900), 4.95);
  EXPECT_DOUBLE_EQ(t.conductivity_at(-50), 50) << "held below";
  EXPECT_DOUBLE_EQ(t.heat_capacity_at(1300), 5.0) << "held above";
  EXPECT_TRUE(t.covers(20) && t.covers(1000));
  EXPECT_FALSE(t.covers(19.9) || t.covers(1000.1));
}

}  // namespace test_thermal_table
