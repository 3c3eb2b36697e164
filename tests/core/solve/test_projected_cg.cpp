// Projected CG reports each iteration with its solve number and stops at the observer's cancel request between
// iterations, returning its current iterate: still feasible (Gᵀλ = e) and nearer the solution than the start.
#include <gtest/gtest.h>

#include "solve/ProjectedCG.h"

using namespace rollsim;

namespace {

/// A 1D Laplacian F (SPD, slow to converge without preconditioner) with one constraint Gᵀλ = e (λ sums to 1).
InterfaceProblem laplacian(int n) {
  InterfaceProblem p;
  p.F = [](const Eigen::VectorXd& x) {
    Eigen::VectorXd y = 2 * x;
    y.head(x.size() - 1) -= x.tail(x.size() - 1);
    y.tail(x.size() - 1) -= x.head(x.size() - 1);
    return y;
  };
  p.b = Eigen::VectorXd::LinSpaced(n, -1, 1);
  p.G = Eigen::MatrixXd::Ones(n, 1);
  p.e = Eigen::VectorXd::Ones(1);
  return p;
}

class Stopper : public AnalysisObserver {
 public:
  explicit Stopper(int after) : after_(after) {}
  void on_cg_iteration(int solve, int iteration, double residual) override {
    EXPECT_EQ(solve, 7);
    EXPECT_EQ(iteration, ++seen_);
    last_ = residual;
  }
  bool cancel_requested() const override { return seen_ >= after_; }
  int seen() const { return seen_; }
  double last() const { return last_; }

 private:
  int after_, seen_ = 0;
  double last_ = 1;
};

}  // namespace

TEST(ProjectedCG, CancelStopsAtTheNextIterationWithAFeasibleIterate) {
  const InterfaceProblem p = laplacian(200);
  ProjectedCGOptions o;
  o.tolerance = 1e-12;
  o.solve = 7;
  Stopper never(1 << 30);
  const ProjectedCGResult full = projected_cg(p, o, &never);
  ASSERT_TRUE(full.converged);
  ASSERT_GT(full.iterations, 20);
  Stopper stop(5);
  const ProjectedCGResult part = projected_cg(p, o, &stop);
  EXPECT_TRUE(part.cancelled);
  EXPECT_FALSE(part.converged);
  EXPECT_EQ(part.iterations, 5);
  EXPECT_EQ(stop.seen(), 5);
  EXPECT_DOUBLE_EQ(part.residuals.back(), stop.last());
  EXPECT_NEAR((p.G.transpose() * part.lambda - p.e).norm(), 0, 1e-12);
  EXPECT_EQ(part.alpha.size(), 1);
  EXPECT_TRUE(part.lambda.allFinite());
  // the first five iterates of both runs are the same
  for (int k = 0; k <= 5; ++k)
    EXPECT_EQ(part.residuals[static_cast<size_t>(k)], full.residuals[static_cast<size_t>(k)]);
  EXPECT_FALSE(full.cancelled);
}
