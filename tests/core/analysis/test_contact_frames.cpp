// analysis.contact_frames: the paper's sticking pass with the stuck points' frames written where each step is expected
// to end converges each step once where step_start converges it, has its projections searched again and converges
// it again — fewer Newton iterations for the same checks — and rolls the same pass.
#include <gtest/gtest.h>

#include "../../common/PassRun.h"
#include "../../common/RollingPass.h"

namespace test_contact_frames {

using namespace rollsim;

TEST(ContactFrames, PredictedFramesSpareTheSecondConvergenceOfEveryStep) {
  nlohmann::json start = testing_support::paper_pass_2d(12, 1.0), predicted = start;
  predicted["analysis"] = {{"contact_frames", "predicted"}};
  const testing_support::PassRun a = testing_support::run_pass(start), b = testing_support::run_pass(predicted);
  ASSERT_EQ(a.status.status, Status::converged) << a.status.message;
  ASSERT_EQ(b.status.status, Status::converged) << b.status.message;
  ASSERT_TRUE(a.rolling && b.rolling);
  ASSERT_EQ(a.increments.size(), b.increments.size());
  EXPECT_LT(static_cast<double>(b.newton.size()), 0.9 * static_cast<double>(a.newton.size()));
  for (size_t i = 0; i < a.rolling->increments.size(); ++i)
    EXPECT_NEAR(b.rolling->increments[i].roll_force / a.rolling->increments[i].roll_force, 1, 1e-4) << i;
}

}  // namespace test_contact_frames
