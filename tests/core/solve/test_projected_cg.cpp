// Projected CG reports each iteration with its solve number and stops at the observer's cancel request between
// iterations, returning its current iterate: still feasible (Gᵀλ = e) and nearer the solution than the start. An
// inexact Newton iteration's tolerance (BlockSystem::InterfaceTolerance) stops it at an absolute residual, or at a
// share of its guess's residual rather than of the least-norm start's.
#include <gtest/gtest.h>

#include "solve/ProjectedCG.h"

namespace test_projected_cg {

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

namespace {
/// F = diag(1..n) (eigenvalues known), b random; `modes` constraint columns: sums of λ over interleaved blocks.
InterfaceProblem diagonal(int n, int modes) {
  InterfaceProblem p;
  p.F = [](const Eigen::VectorXd& x) {
    return Eigen::VectorXd(Eigen::VectorXd::LinSpaced(x.size(), 1, x.size()).cwiseProduct(x));
  };
  p.b = Eigen::VectorXd::LinSpaced(n, -1, 1).array().sin();
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < n; ++i) t.emplace_back(i, i % modes, 1.0 + 0.01 * i);
  p.Gs.resize(n, modes);
  p.Gs.setFromTriplets(t.begin(), t.end());
  p.e = Eigen::VectorXd::LinSpaced(modes, 1, 2);
  return p;
}
}  // namespace

TEST(ProjectedCG, WeightedProjectorReachesTheSameSolution) {
  // Q = diag(q) SPD: the constrained minimiser and its multipliers α do not depend on Q, only the path does
  InterfaceProblem p = diagonal(60, 3);
  ProjectedCGOptions o;
  o.tolerance = 1e-12;
  const ProjectedCGResult euclid = projected_cg(p, o);
  const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(60, 0.5, 3.0);
  const SparseMatrix QG = q.asDiagonal() * p.Gs;
  p.QG = &QG;
  o.preconditioner = [&](const Eigen::VectorXd& w) { return Eigen::VectorXd(q.cwiseProduct(w)); };
  const ProjectedCGResult weighted = projected_cg(p, o);
  ASSERT_TRUE(euclid.converged && weighted.converged);
  EXPECT_LT((weighted.lambda - euclid.lambda).norm() / euclid.lambda.norm(), 1e-9);
  EXPECT_LT((weighted.alpha - euclid.alpha).norm() / euclid.alpha.norm(), 1e-9);
  EXPECT_LT((p.Gs.transpose() * weighted.lambda - p.e).norm(), 1e-12) << "Gᵀλ = e with the weighted projector";
  EXPECT_NE(weighted.iterations, 0);
}

TEST(ProjectedCG, EigenvalueEstimatesBracketTheOperatorsSpectrum) {
  // unconstrained F = diag(1..40): a full Krylov space gives the extreme eigenvalues 1 and 40
  InterfaceProblem p = diagonal(40, 1);
  p.Gs.resize(40, 0);
  p.e.resize(0);
  ProjectedCGOptions o;
  o.tolerance = 1e-14;
  const ProjectedCGResult r = projected_cg(p, o);
  ASSERT_GE(r.iterations, 20);
  EXPECT_NEAR(r.lambda_max, 40.0, 1e-3 * 40);
  EXPECT_GT(r.lambda_min, 1.0 - 1e-6);
  EXPECT_LT(r.lambda_min, 1.5);
  // the Ritz values lie inside the spectrum after any number of iterations
  o.tolerance = 1e-2;
  const ProjectedCGResult early = projected_cg(p, o);
  EXPECT_GE(early.lambda_min, 1.0 - 1e-9);
  EXPECT_LE(early.lambda_max, 40.0 + 1e-9);
}

// A guess near the solution (the last Newton iteration's λ) is moved onto Gᵀλ = e and saves iterations; the tolerance
// stays relative to the least-norm start's residual, so the answer is as accurate. A guess farther than that start
// is not taken.
TEST(ProjectedCG, StartsFromAGuessWithTheToleranceOfTheLeastNormStart) {
  InterfaceProblem p = laplacian(200);
  ProjectedCGOptions o;
  o.tolerance = 1e-8;
  const ProjectedCGResult cold = projected_cg(p, o);
  ASSERT_TRUE(cold.converged);
  p.start = cold.lambda + 1e-4 * Eigen::VectorXd::LinSpaced(200, 0, 1).array().sin().matrix();  // infeasible
  const ProjectedCGResult warm = projected_cg(p, o);
  ASSERT_TRUE(warm.converged);
  EXPECT_LT(warm.residuals[0], 1e-2);
  EXPECT_LT(warm.iterations, cold.iterations * 3 / 4);
  EXPECT_NEAR((p.G.transpose() * warm.lambda)(0), 1.0, 1e-10);
  EXPECT_LT((warm.lambda - cold.lambda).norm(), 1e-5 * cold.lambda.norm());
  p.start = Eigen::VectorXd::Constant(200, 1e6);
  const ProjectedCGResult far = projected_cg(p, o);
  EXPECT_EQ(far.residuals[0], 1.0);
  EXPECT_EQ(far.iterations, cold.iterations);
  EXPECT_EQ(far.lambda, cold.lambda);
}

TEST(ProjectedCG, StopsAtAnAbsoluteResidualOrAShareOfItsGuesssResidual) {
  InterfaceProblem p = laplacian(200);
  ProjectedCGOptions o;
  o.tolerance = 1e-12;
  const ProjectedCGResult exact = projected_cg(p, o);
  o.absolute = 1e-3 * p.b.norm();
  const ProjectedCGResult loose = projected_cg(p, o);
  EXPECT_TRUE(loose.converged);
  EXPECT_LT(loose.iterations, exact.iterations);
  // a guess near the answer: 1e-2 of the least-norm start's residual is met at once, 1e-2 of the guess's is not
  p.start = exact.lambda + 1e-6 * Eigen::VectorXd::LinSpaced(200, -1, 1);
  o = ProjectedCGOptions{};
  o.tolerance = 1e-2;
  EXPECT_EQ(projected_cg(p, o).iterations, 0);
  o.relative_to_start = true;
  const ProjectedCGResult from_guess = projected_cg(p, o);
  EXPECT_TRUE(from_guess.converged);
  EXPECT_GT(from_guess.iterations, 0);
  EXPECT_LE(from_guess.residuals.back(), 1e-2 * from_guess.residuals.front());
}

}  // namespace test_projected_cg
