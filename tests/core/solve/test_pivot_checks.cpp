// Factorizations refuse matrices singular to working precision instead of returning garbage: a negative pivot in
// the positive definite part of the skyline (it accepted any pivot above 1e-13 of the largest), a pivot of 1e-14 of
// its diagonal in CHOLMOD (it accepted any positive one); a matrix with condition ~1e8 is factored and its smallest
// pivot ratio reported.
#include <gtest/gtest.h>

#include "solve/CholmodFactorization.h"
#include "solve/SkylineFactorization.h"

namespace test_pivot_checks {

using namespace rollsim;

namespace {

/// [[1, 1], [1, 1 + delta]] padded with a well-conditioned diagonal block: pivot ratio of column 1 is delta / (1 +
/// delta).
SparseMatrix nearly_singular(double delta) {
  const int n = 6;
  std::vector<Eigen::Triplet<double, int>> t{{0, 0, 1.0}, {0, 1, 1.0}, {1, 0, 1.0}, {1, 1, 1.0 + delta}};
  for (int i = 2; i < n; ++i) t.emplace_back(i, i, 4.0);
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

void expect_refused(Factorization& factorization, double delta, const std::string& fragment) {
  const SparseMatrix A = nearly_singular(delta);
  try {
    factorization.factorize(A);
    FAIL() << "expected SingularMatrix for delta " << delta;
  } catch (const SingularMatrix& e) {
    EXPECT_TRUE(e.column == 0 || e.column == 1) << e.column;
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

void expect_solved(Factorization& factorization, double delta) {
  const SparseMatrix A = nearly_singular(delta);
  factorization.factorize(A);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(6, 1, 6);
  const Eigen::VectorXd y = factorization.solve(A * x);
  EXPECT_LT((y - x).norm() / x.norm(), 1e-6);
  EXPECT_NEAR(factorization.stats().min_pivot_ratio, delta, 1e-2 * delta);
}

}  // namespace

TEST(PivotChecks, SkylineRefusesANegativePivotAboveTheOldThreshold) {
  SkylineFactorization f;
  expect_refused(f, -1e-10, "non-positive pivot");
}

TEST(PivotChecks, SkylineRefusesAPivotLostToCancellation) {
  SkylineFactorization f;
  expect_refused(f, 1e-14, "of its diagonal");
}

TEST(PivotChecks, CholmodRefusesAPivotLostToCancellation) {
  CholmodFactorization f;
  expect_refused(f, 1e-14, "of its diagonal");
}

TEST(PivotChecks, IllConditionedButSolvableMatricesAreFactored) {
  SkylineFactorization skyline;
  expect_solved(skyline, 1e-8);
  CholmodFactorization cholmod;
  expect_solved(cholmod, 1e-8);
}

namespace {
/// [K cᵀ; c 0] with K = k I (4 × 4) and one or two constraint rows c = (1, 1, 0, 0) (the second a copy: singular).
SparseMatrix saddle(double k, bool duplicate_row) {
  const int n = 4, m = duplicate_row ? 2 : 1;
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, k);
  for (int r = 0; r < m; ++r)
    for (int i : {0, 1}) {
      t.emplace_back(n + r, i, 1.0);
      t.emplace_back(i, n + r, 1.0);
    }
  SparseMatrix A(n + m, n + m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}
}  // namespace

TEST(PivotChecks, SkylineJudgesMultiplierPivotsOnTheirOwnScale) {
  // a multiplier pivot is −c K⁻¹ cᵀ = −2 / k: 2e-7 beside stiffness pivots of 1e7 (Example 2's cylinder) is not
  // singular — it was refused against 1e-13 of the largest pivot; a repeated constraint row still is
  SkylineFactorization stiff(1);
  stiff.factorize(saddle(1e7, false));
  const Eigen::VectorXd x = (Eigen::VectorXd(5) << 1, 2, 3, 4, 5).finished();
  EXPECT_LT((stiff.solve(saddle(1e7, false) * x) - x).norm() / x.norm(), 1e-9);
  SkylineFactorization redundant(2);
  EXPECT_THROW(redundant.factorize(saddle(1e7, true)), SingularMatrix);
}

}  // namespace test_pivot_checks
