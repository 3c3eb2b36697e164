// Projected GMRES solves the unsymmetric interface problem F λ − G α = b, G̃ᵀλ = e (slipping Coulomb friction under
// mixed / feti: the modes' columns G = C R differ from the constraint's G̃ = C_eq R) to the dense solution, with or
// without a preconditioner and across restarts; with G̃ = G and F symmetric it gives projected CG's answer.
#include <gtest/gtest.h>

#include "solve/ProjectedGMRES.h"

namespace test_projected_gmres {

using namespace rollsim;

namespace {
struct Dense {
  Eigen::MatrixXd F, G, Gt;
  Eigen::VectorXd b, e;
};

/// A convection–diffusion stencil (unsymmetric, positive real part) of size n with two modes; the nearer `diagonal`
/// is to 2, the worse conditioned.
Dense problem(int n, double convection, bool same_modes, double diagonal = 2.5) {
  Dense d;
  d.F = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    d.F(i, i) = diagonal;
    if (i > 0) d.F(i, i - 1) = -1 - convection;
    if (i + 1 < n) d.F(i, i + 1) = -1 + convection;
  }
  d.G = Eigen::MatrixXd::Zero(n, 2);
  for (int i = 0; i < n; ++i) d.G(i, 0) = 1, d.G(i, 1) = double(i) / n;
  d.Gt = d.G;
  if (!same_modes) d.Gt.col(1) += 0.3 * Eigen::VectorXd::LinSpaced(n, 0, 1).array().square().matrix();
  d.b = Eigen::VectorXd::LinSpaced(n, -1, 2).array().sin();
  d.e = Eigen::Vector2d(0.5, -0.25);
  return d;
}

InterfaceProblem interface(const Dense& d) {
  InterfaceProblem p;
  p.F = [&d](const Eigen::VectorXd& x) { return Eigen::VectorXd(d.F * x); };
  p.b = d.b, p.e = d.e;
  p.Gs = d.G.sparseView();
  p.Gt = d.Gt.sparseView();
  p.unsymmetric = true;
  return p;
}

/// [F −G; G̃ᵀ 0] [λ; α] = [b; e], densely
std::pair<Eigen::VectorXd, Eigen::VectorXd> exact(const Dense& d) {
  const Eigen::Index n = d.F.rows(), k = d.G.cols();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + k, n + k);
  A.topLeftCorner(n, n) = d.F;
  A.topRightCorner(n, k) = -d.G;
  A.bottomLeftCorner(k, n) = d.Gt.transpose();
  Eigen::VectorXd rhs(n + k);
  rhs << d.b, d.e;
  const Eigen::VectorXd x = A.fullPivLu().solve(rhs);
  return {x.head(n), x.tail(k)};
}
}  // namespace

TEST(ProjectedGMRES, SolvesTheObliqueProblemToTheDenseSolution) {
  const Dense d = problem(40, 0.4, false);
  const auto [lambda, alpha] = exact(d);
  ProjectedCGOptions o{1e-12, 1000, {}, 1};
  const ProjectedCGResult r = projected_gmres(interface(d), o);
  ASSERT_TRUE(r.converged);
  EXPECT_LT((r.lambda - lambda).norm(), 1e-9 * lambda.norm());
  EXPECT_LT((r.alpha - alpha).norm(), 1e-9 * alpha.norm());
  EXPECT_LT((d.Gt.transpose() * r.lambda - d.e).norm(), 1e-12);  // every iterate stays feasible
  // a (Jacobi) preconditioner changes the path, not the answer
  o.preconditioner = [](const Eigen::VectorXd& w) { return Eigen::VectorXd(w / 2.5); };
  const ProjectedCGResult pre = projected_gmres(interface(d), o);
  ASSERT_TRUE(pre.converged);
  EXPECT_LT((pre.lambda - lambda).norm(), 1e-9 * lambda.norm());
}

TEST(ProjectedGMRES, RestartsAndStillConverges) {
  const Dense d = problem(600, 0.05, false, 2.002);  // more than one cycle of 200 iterations
  const auto [lambda, alpha] = exact(d);
  const ProjectedCGResult r = projected_gmres(interface(d), {1e-10, 5000, {}, 1});
  ASSERT_TRUE(r.converged) << r.iterations << " iterations, residual " << r.residuals.back();
  EXPECT_GT(r.iterations, 200);
  EXPECT_LT((r.lambda - lambda).norm(), 1e-7 * lambda.norm());
}

TEST(ProjectedGMRES, OnASymmetricProblemItGivesProjectedCGsAnswer) {
  Dense d = problem(50, 0.0, true);
  InterfaceProblem p = interface(d);
  p.Gt.resize(0, 0);
  p.unsymmetric = false;
  const ProjectedCGOptions o{1e-12, 1000, {}, 1};
  const ProjectedCGResult g = projected_gmres(p, o), c = projected_cg(p, o);
  ASSERT_TRUE(g.converged && c.converged);
  EXPECT_LT((g.lambda - c.lambda).norm(), 1e-9 * c.lambda.norm());
  EXPECT_LT((g.alpha - c.alpha).norm(), 1e-9 * c.alpha.norm());
}

TEST(ProjectedGMRES, StartsFromAGuessWithTheToleranceOfTheLeastNormStart) {
  const Dense d = problem(300, 0.05, false, 2.02);
  const auto [lambda, alpha] = exact(d);
  InterfaceProblem p = interface(d);
  const ProjectedCGOptions o{1e-10, 5000, {}, 1};
  const ProjectedCGResult cold = projected_gmres(p, o);
  ASSERT_TRUE(cold.converged);
  p.start = lambda + 1e-4 * Eigen::VectorXd::LinSpaced(300, 0, 3).array().cos().matrix();  // off G̃ᵀλ = e
  const ProjectedCGResult warm = projected_gmres(p, o);
  ASSERT_TRUE(warm.converged);
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_LT((d.Gt.transpose() * warm.lambda - d.e).norm(), 1e-10);
  EXPECT_LT((warm.lambda - lambda).norm(), 1e-7 * lambda.norm());
}

TEST(ProjectedGMRES, ACycleEndsWhereItsKrylovSpaceReachesTheNullSpaceOfF) {
  // F singular on ker G̃ᵀ: the last multiplier acts on no dof (a zero row and column of F), and the data hold a
  // round-off share of it. Once the Krylov space reaches that null vector, a triangular solve of the cycle's
  // least-squares problem divides by a round-off pivot (λ off by 5 here, and off its constraint); the cycle must
  // end before it and report the round-off level of its data.
  Dense d = problem(40, 0.3, false);
  const Eigen::Index n = d.F.rows();
  d.F.row(n - 1).setZero(), d.F.col(n - 1).setZero();
  d.G.row(n - 1).setZero(), d.Gt.row(n - 1).setZero();
  d.b[n - 1] = 1e-15;
  Dense regular = d;  // the same problem with that multiplier held at 0
  regular.F(n - 1, n - 1) = 1, regular.b[n - 1] = 0;
  const auto [lambda, alpha] = exact(regular);
  // a tolerance below the inconsistency: GMRES runs until its Krylov space is exhausted
  const ProjectedCGResult r = projected_gmres(interface(d), {1e-18, 3 * static_cast<int>(n), {}, 1});
  EXPECT_TRUE(r.round_off);
  EXPECT_LT(r.residuals.back(), 1e-10) << "down to the inconsistency's size";
  EXPECT_LT((d.Gt.transpose() * r.lambda - d.e).norm(), 1e-12) << "still feasible";
  EXPECT_LT((r.lambda.head(n - 1) - lambda.head(n - 1)).norm(), 1e-9 * lambda.norm());
  EXPECT_LT(std::abs(r.lambda[n - 1]), 1e-6 * lambda.norm()) << "the free multiplier stays small";
}

}  // namespace test_projected_gmres
