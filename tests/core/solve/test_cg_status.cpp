// How a projected CG that does not converge says so: iteration limit, breakdown on an operator that is not positive
// definite, the round-off floor above the tolerance — each a not_converged status with its reason and a message
// naming the iterations, the residual reached and the tolerance; the exit codes of the status vocabulary.
#include <gtest/gtest.h>

#include "solve/ProjectedCG.h"

namespace test_cg_status {

using namespace rollsim;

namespace {

/// F = diag(1 … n) (SPD, n distinct eigenvalues: CG needs n iterations), b = ones, no rigid modes.
InterfaceProblem diagonal(int n, double sign_of_last = 1) {
  InterfaceProblem p;
  p.F = [n, sign_of_last](const Eigen::VectorXd& x) {
    Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(n, 1, n).cwiseProduct(x);
    y[n - 1] *= sign_of_last;
    return y;
  };
  p.b = Eigen::VectorXd::Ones(n);
  return p;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(CgStatus, IterationLimitIsNotConverged) {
  const ProjectedCGOptions o{1e-10, 5, {}, 1};
  const ProjectedCGResult r = projected_cg(diagonal(40), o);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 5);
  const RunStatus s = cg_status(r, o);
  EXPECT_EQ(s.status, Status::not_converged);
  EXPECT_EQ(s.reason, Reason::iteration_limit);
  EXPECT_TRUE(contains(s.message, "iteration limit (5)")) << s.message;
  EXPECT_TRUE(contains(s.message, "tolerance 1e-10")) << s.message;
}

TEST(CgStatus, IndefiniteOperatorBreaksDown) {
  const ProjectedCGOptions o{1e-10, 1000, {}, 1};
  const ProjectedCGResult r = projected_cg(diagonal(40, -1), o);  // one negative eigenvalue
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(r.breakdown);
  const RunStatus s = cg_status(r, o);
  EXPECT_EQ(s.status, Status::not_converged);
  EXPECT_EQ(s.reason, Reason::breakdown);
  EXPECT_TRUE(contains(s.message, "broke down")) << s.message;
}

TEST(CgStatus, ToleranceBelowRoundOffIsNotConvergedButReachableOneConverges) {
  const ProjectedCGOptions tight{1e-300, 1000, {}, 1};
  const ProjectedCGResult r = projected_cg(diagonal(40), tight);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(r.round_off);
  EXPECT_EQ(cg_status(r, tight).reason, Reason::round_off);
  const ProjectedCGOptions fair{1e-10, 1000, {}, 1};
  const ProjectedCGResult ok = projected_cg(diagonal(40), fair);
  EXPECT_TRUE(ok.converged);
  EXPECT_TRUE(cg_status(ok, fair).ok());
  EXPECT_LE(ok.residuals.back(), 1e-10);
}

TEST(CgStatus, ExitCodesOfTheVocabulary) {
  EXPECT_EQ(exit_code(Status::converged), 0);
  EXPECT_EQ(exit_code(Status::error), 2);
  EXPECT_EQ(exit_code(Status::not_converged), 3);
  EXPECT_EQ(exit_code(Status::diverged), 4);
  EXPECT_EQ(exit_code(Status::cancelled), 5);
  EXPECT_STREQ(to_string(Status::not_converged), "not_converged");
  EXPECT_STREQ(to_string(Reason::active_set_cycling), "active_set_cycling");
}

}  // namespace test_cg_status
