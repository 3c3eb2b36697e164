// CholeskyOrLU: CHOLMOD's LLᵀ for a positive definite matrix (no LU made), UMFPACK's LU for an indefinite one (and
// kept for the next values), a refusal for a singular one and for a tiny positive pivot (singular to working
// precision, not indefinite).
#include <gtest/gtest.h>

#include "solve/CholeskyOrLU.h"
#include "solve_error.h"

namespace test_cholesky_or_lu {

using namespace rollsim;

namespace {
/// A chain of n nodes with springs k between neighbours and `ground` at node 0: the Laplacian plus ground e0 e0ᵀ.
SparseMatrix chain(int n, double k, double ground) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i + 1 < n; ++i)
    for (auto [a, b, s] : {std::tuple{i, i, k}, {i + 1, i + 1, k}, {i, i + 1, -k}, {i + 1, i, -k}})
      t.emplace_back(a, b, s);
  t.emplace_back(0, 0, ground);
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}
}  // namespace

TEST(CholeskyOrLU, PositiveDefiniteStaysCholesky) {
  CholeskyOrLU f;
  const SparseMatrix A = chain(20, 1.0, 1.0);
  f.analyze(A);
  f.factorize(A);
  EXPECT_FALSE(f.indefinite());
  EXPECT_LT(rollsim::testing::relative_solve_error(f, A), 1e-12);
  EXPECT_EQ(f.stats().factorizations, 1);
}

TEST(CholeskyOrLU, IndefiniteGoesToLUAndStaysThere) {
  CholeskyOrLU f;
  const SparseMatrix indefinite = chain(20, 1.0, -0.5);  // one negative eigenvalue, regular
  f.analyze(indefinite);
  f.factorize(indefinite);
  EXPECT_TRUE(f.indefinite());
  EXPECT_LT(rollsim::testing::relative_solve_error(f, indefinite), 1e-12);
  const SparseMatrix definite = chain(20, 1.0, 1.0);  // later values: the LU, which serves them as well
  f.factorize(definite);
  EXPECT_TRUE(f.indefinite());
  EXPECT_LT(rollsim::testing::relative_solve_error(f, definite), 1e-12);
}

TEST(CholeskyOrLU, SingularIsRefused) {
  CholeskyOrLU f;
  const SparseMatrix A = chain(20, 1.0, 0.0);  // floating chain: kernel = ones
  f.analyze(A);
  EXPECT_THROW(f.factorize(A), SingularMatrix);
  const SparseMatrix rank_deficient = chain(20, 1.0, -1e-18);  // indefinite by a hair, singular to working precision
  CholeskyOrLU g;
  g.analyze(rank_deficient);
  EXPECT_THROW(g.factorize(rank_deficient), SingularMatrix);
}

TEST(CholeskyOrLU, TinyPositivePivotIsRefusedWithoutLU) {
  CholeskyOrLU f;
  const SparseMatrix A = chain(20, 1.0, 1e-15);  // positive definite, condition ~1e17
  f.analyze(A);
  try {
    f.factorize(A);
    FAIL() << "expected SingularMatrix";
  } catch (const SingularMatrix& e) {
    EXPECT_NE(std::string(e.what()).find("of its diagonal"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(f.indefinite());
}

}  // namespace test_cholesky_or_lu
