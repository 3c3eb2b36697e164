// A pass in mill terms before it runs: the paper's pass reads 13.2 %, Ø 600 mm, α 12.04°, L 62.9 mm and bites with
// sticking friction; Coulomb μ 0.15 below tan α does not bite and says so as a warning; a roll speed adds the surface
// speed, the time in the gap, the mean strain rate and the power; a pass longer than its slab names where it ends,
// at the travel the slab's rear end needs by continuity (the main job's run ended at 261 mm of the predicted 267).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "process/rolling/RollingFacts.h"
#include "process/rolling/RollingTheory.h"

namespace test_rolling_facts {

using namespace rollsim;

namespace {
RollingPass paper_pass() {
  RollingPass p;
  p.radius = 300, p.entry_thickness = 100, p.exit_thickness = 86.8, p.flow_stress = 100, p.width = 350;
  p.slab_length = 300, p.travel = 120;
  return p;
}

const ProcessFact* fact(const std::vector<ProcessFact>& facts, const std::string& name) {
  for (const ProcessFact& f : facts)
    if (f.name == name) return &f;
  return nullptr;
}
}  // namespace

TEST(RollingFacts, ThePapersPassInMillTerms) {
  const auto facts = rolling_facts(paper_pass(), 2);
  ASSERT_NE(fact(facts, "bite angle"), nullptr);
  EXPECT_EQ(fact(facts, "reduction")->value, "13.2 %");
  EXPECT_EQ(fact(facts, "roll")->value, "Ø 600 mm");
  EXPECT_EQ(fact(facts, "roll")->note, "R = 300 mm");
  RollingPass fixed = paper_pass();
  fixed.roll_fixed = true;  // process.roll_mesh: fixed, said beside the roll
  EXPECT_NE(fact(rolling_facts(fixed, 2), "roll")->note.find("its mesh fixed, its surface turning"), std::string::npos);
  EXPECT_EQ(fact(facts, "bite angle")->value, "12.04°");
  EXPECT_EQ(fact(facts, "contact length")->value, "62.9 mm");
  EXPECT_EQ(fact(facts, "bites")->value, "yes");
  EXPECT_FALSE(fact(facts, "bites")->warning);
  // Sims's 6.78 kN/mm, and over the 350 mm width 2.37 MN
  EXPECT_EQ(fact(facts, "roll force (Sims)")->value, "6.781 kN/mm");
  EXPECT_NE(fact(facts, "roll force (Sims)")->note.find("2.37 MN"), std::string::npos);
  // no speed given: nothing that needs one; 120 mm of travel ends before the slab is through
  EXPECT_EQ(fact(facts, "mean strain rate"), nullptr);
  EXPECT_EQ(fact(facts, "end of the pass"), nullptr);
}

TEST(RollingFacts, ACoulombPassBelowTheBiteAngleIsAWarning) {
  RollingPass p = paper_pass();
  p.friction = 0.15;  // tan 12.04° = 0.213
  const auto facts = rolling_facts(p, 2);
  const ProcessFact* bites = fact(facts, "bites");
  ASSERT_NE(bites, nullptr);
  EXPECT_EQ(bites->value, "no");
  EXPECT_TRUE(bites->warning);
  EXPECT_NE(bites->note.find("tan α = 0.213"), std::string::npos) << bites->note;
  p.friction = 0.3;
  const auto biting = rolling_facts(p, 2);
  EXPECT_EQ(fact(biting, "bites")->value, "yes");
}

TEST(RollingFacts, ARollSpeedGivesSpeedTimeStrainRateAndPower) {
  RollingPass p = paper_pass();
  p.rpm = 60;  // ω = 2π 1/s, v = 2π · 300 mm/s = 1.885 m/s
  const auto facts = rolling_facts(p, 2);
  ASSERT_NE(fact(facts, "roll surface speed"), nullptr);
  EXPECT_EQ(fact(facts, "roll surface speed")->value, "1.88 m/s");
  const double v = 2 * M_PI * 300, L = std::sqrt(300 * 13.2);
  char expected[40];
  std::snprintf(expected, sizeof expected, "%.3g 1/s",
                2 / std::sqrt(3.0) * std::log(100 / 86.8) * v / L);  // equivalent
  EXPECT_EQ(fact(facts, "mean strain rate")->value, expected);
  std::snprintf(expected, sizeof expected, "%.3g ms", 1e3 * L / v);
  EXPECT_EQ(fact(facts, "time in the roll gap")->value, expected);
  // power per roll and unit width: Sims's torque × ω [N·mm/s per mm = 1e-6 kW/mm]
  std::snprintf(expected, sizeof expected, "%.4g kW/mm", rolling_theory(p).sims_torque * 2 * M_PI / 1e6);
  EXPECT_EQ(fact(facts, "roll power (Sims)")->value, expected);
  std::snprintf(expected, sizeof expected, "%.3g s", 120 / v);
  EXPECT_EQ(fact(facts, "time of the pass")->value, expected);
}

TEST(RollingFacts, APassLongerThanItsSlabSaysWhereItEnds) {
  RollingPass p = paper_pass();
  p.travel = 500;
  // continuity: the rear end, 300 − 62.9 mm from the gap's entry, moves at h1 (1 + Sims's slip) / h0 of the roll
  const double through = (300 - std::sqrt(300 * 13.2)) * 100 / (86.8 * (1 + rolling_theory(p).sims_forward_slip));
  EXPECT_NEAR(travel_through(p), through, 1e-9);
  EXPECT_NEAR(through, 267, 1);
  const auto facts = rolling_facts(p, 2);
  const ProcessFact* end = fact(facts, "end of the pass");
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(end->value, "travel ≈ 267 of 500 mm");
}

// A crowned roll, 0.5 mm smaller in radius 100 mm from the centre, on the 350 mm slab: the radius changes by 0 to
// −0.5 mm across it, and the 86.8 mm exit leaves 86.8 to 87.8 mm thick.
TEST(RollingFacts, ACrownedRollSaysHowThickTheSlabLeavesAcrossItsWidth) {
  RollingPass p = paper_pass();
  EXPECT_EQ(fact(rolling_facts(p, 3), "roll profile"), nullptr);
  p.profile.points = {{0.0, 0.0}, {100.0, -0.5}};
  const auto facts = rolling_facts(p, 3);
  const ProcessFact* f = fact(facts, "roll profile");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->value, "Δr -0.5 to 0 mm");
  EXPECT_NE(f->note.find("leaves 86.8 to 87.8 mm thick"), std::string::npos) << f->note;
}

}  // namespace test_rolling_facts
