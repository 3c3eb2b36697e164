// The forcing terms of analysis.forcing: `fixed` asks solver.cg_tolerance of every solve; `eisenstat_walker` starts a
// step at its loosest tolerance, keeps it while the Newton residual falls slowly, tightens as it falls fast, never
// goes below its floor, takes the floor at once for an iterate that is balanced, and starts again loose each step.
#include <gtest/gtest.h>

#include "analysis/ForcingSequence.h"

namespace test_forcing_sequence {

using namespace rollsim;

TEST(ForcingSequence, FixedAsksTheSameToleranceOfEverySolve) {
  ForcingSequence f(Forcing::Fixed, 1e-10, 1e-6);
  for (double r : {1.0, 1e-3, 1e-9}) {
    const InterfaceTolerance t = f.next(r, false, 1e-7);
    EXPECT_EQ(t.relative, 1e-10);
    EXPECT_EQ(t.absolute, 0.0);
    EXPECT_FALSE(t.from_last);  // of the least-norm start's residual, as always
  }
  EXPECT_EQ(f.next(1e-12, true, 1e-7).relative, 1e-10);
}

TEST(ForcingSequence, LoosensEarlyTightensAsTheResidualFallsNeverBelowTheFloor) {
  ForcingSequence f(Forcing::EisenstatWalker, 1e-2, 1e-10);
  std::vector<double> eta;
  for (double r : {1.0, 0.5, 1e-2, 1e-6, 1e-14, 1e-24}) eta.push_back(f.next(r, false, 0.0).relative);
  EXPECT_EQ(eta[0], 1e-2);                        // the step's first solve: the loosest
  EXPECT_EQ(eta[1], 1e-2);                        // a slow fall (0.9 × 0.5² = 0.225): capped at the loosest
  EXPECT_NEAR(eta[2], 0.9 * 0.02 * 0.02, 1e-15);  // 0.9 (‖r_k‖ / ‖r_k−1‖)²
  EXPECT_NEAR(eta[3], 0.9 * 1e-8, 1e-20);
  EXPECT_EQ(eta[4], 1e-10);  // 0.9 × 1e-16 is below the floor
  EXPECT_EQ(eta[5], 1e-10);  // (η follows the residual's fall, not its level: 1e-24 after 1e-14 falls 1e-10)
  for (size_t k = 1; k < eta.size(); ++k) EXPECT_LE(eta[k], eta[k - 1]);
}

TEST(ForcingSequence, AGrowingResidualLoosensAgainAndTheSafeguardHoldsATightenedEtaBack) {
  ForcingSequence f(Forcing::EisenstatWalker, 0.5, 1e-10);
  EXPECT_EQ(f.next(1.0, false, 0).relative, 0.5);
  // 0.9 × 0.1² = 0.009, but γ η² = 0.9 × 0.25 = 0.225 > 0.1: η may not fall faster than that
  EXPECT_NEAR(f.next(0.1, false, 0).relative, 0.225, 1e-15);
  EXPECT_EQ(f.next(10.0, false, 0).relative, 0.5);  // the residual grew: loosest again
}

TEST(ForcingSequence, ABalancedIterateTakesTheFloorAndTheConstraintsAbsoluteTolerance) {
  ForcingSequence f(Forcing::EisenstatWalker, 1e-2, 1e-10);
  f.next(1.0, false, 0);
  const InterfaceTolerance t = f.next(1e-9, true, 3e-7);
  EXPECT_EQ(t.relative, 1e-10);
  EXPECT_EQ(t.absolute, 3e-7);
  EXPECT_TRUE(t.from_last);  // of the residual at the last λ: the correction's
}

TEST(ForcingSequence, EachStepStartsLooseAgain) {
  ForcingSequence f(Forcing::EisenstatWalker, 1e-2, 1e-10);
  f.next(1.0, false, 0);
  EXPECT_LT(f.next(1e-8, false, 0).relative, 1e-2);
  f.restart();
  EXPECT_EQ(f.next(1e-8, false, 0).relative, 1e-2);
}

TEST(ForcingSequence, AFloorAboveTheLoosestIsTheLoosest) {
  ForcingSequence f(Forcing::EisenstatWalker, 1e-12, 1e-10);
  EXPECT_EQ(f.floor(), 1e-12);
  EXPECT_EQ(f.next(1.0, false, 0).relative, 1e-12);
  EXPECT_EQ(f.next(1e-9, false, 0).relative, 1e-12);
}

}  // namespace test_forcing_sequence
