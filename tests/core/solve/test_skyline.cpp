// Tests of the skyline active-column LDL^T: accuracy against dense and CHOLMOD solves, flop count, singularity.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <iostream>
#include <random>
#include <vector>

#include "solve/CholmodFactorization.h"
#include "solve/ReverseCuthillMcKee.h"
#include "solve/SkylineFactorization.h"

namespace rollsim::test_skyline {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

SparseMatrix from_triplets(int n, const Triplets& t) {
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// 5-point Laplacian (Dirichlet-like: diagonal 4) on an nx-by-ny grid plus `shift` times the identity.
SparseMatrix grid_laplacian(int nx, int ny, double shift) {
  Triplets t;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const int v = x + nx * y;
      t.emplace_back(v, v, 4.0 + shift);
      if (x + 1 < nx) t.emplace_back(v, v + 1, -1.0), t.emplace_back(v + 1, v, -1.0);
      if (y + 1 < ny) t.emplace_back(v, v + nx, -1.0), t.emplace_back(v + nx, v, -1.0);
    }
  return from_triplets(nx * ny, t);
}

/// Random symmetric sparse matrix made SPD by strict diagonal dominance.
SparseMatrix random_spd(int n, int couplings_per_row, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Triplets t;
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < couplings_per_row; ++k) {
      const int j = static_cast<int>(rng() % static_cast<unsigned>(n));
      if (j == i) continue;
      const double v = value(rng);
      t.emplace_back(i, j, v), t.emplace_back(j, i, v);
      row_sum[i] += std::abs(v), row_sum[j] += std::abs(v);
    }
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, row_sum[i] + 1.0 + std::abs(value(rng)));
  return from_triplets(n, t);
}

/// [K C^T; C 0] with K a grid Laplacian and C `m` constraints, each tying two or three distinct dofs.
SparseMatrix saddle_point(int nx, int ny, int m, unsigned seed) {
  const SparseMatrix K = grid_laplacian(nx, ny, 0.0);
  const int n = nx * ny;
  std::mt19937 rng(seed);
  Triplets t;
  for (int c = 0; c < n; ++c)
    for (SparseMatrix::InnerIterator it(K, c); it; ++it) t.emplace_back(static_cast<int>(it.row()), c, it.value());
  for (int r = 0; r < m; ++r) {
    const int own = r * (n / m);  // a distinct dof per constraint keeps C of full row rank
    const int other = static_cast<int>(rng() % static_cast<unsigned>(n));
    const double coeffs[2] = {1.0, -0.5 - 0.5 * (r % 3)};
    const int dofs[2] = {own, other};
    for (int k = 0; k < (other == own ? 1 : 2); ++k)
      t.emplace_back(n + r, dofs[k], coeffs[k]), t.emplace_back(dofs[k], n + r, coeffs[k]);
  }
  return from_triplets(n + m, t);
}

Eigen::VectorXd random_vector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b[i] = value(rng);
  return b;
}

double relative_difference(const Eigen::VectorXd& x, const Eigen::VectorXd& ref) {
  return (x - ref).norm() / ref.norm();
}

/// Operation count of the Crout active-column LDL^T from the column heights alone (independent re-derivation).
double flops_from_profile(const std::vector<int>& first) {
  double flops = 0;
  for (size_t j = 0; j < first.size(); ++j)
    for (int i = first[j]; i < static_cast<int>(j); ++i) flops += 2.0 * (i - std::max(first[i], first[j])) + 3.0;
  return flops;
}

TEST(SkylineTest, GridLaplacianMatchesDenseLltAndCholmod) {
  const SparseMatrix A = grid_laplacian(30, 20, 1.0);
  const Eigen::VectorXd b = random_vector(600, 1);
  SkylineFactorization sky;
  sky.analyze(A);
  sky.factorize(A);
  const Eigen::VectorXd x = sky.solve(b);
  const Eigen::VectorXd dense = Eigen::MatrixXd(A).llt().solve(b);
  EXPECT_LT(relative_difference(x, dense), 1e-10);
  CholmodFactorization chol;
  chol.analyze(A);
  chol.factorize(A);
  EXPECT_LT(relative_difference(x, chol.solve(b)), 1e-10);
  EXPECT_EQ(sky.stats().ordering, "RCM");
  EXPECT_EQ(sky.stats().factorizations, 1);
  EXPECT_EQ(sky.stats().nnz_factor, static_cast<double>(profile_size(A, sky.permutation())));
  EXPECT_LT(sky.stats().nnz_factor, 600.0 * 25);  // RCM bandwidth is about the short side of the grid
}

TEST(SkylineTest, RandomSparseSpdMatchesDenseLdltAndCholmod) {
  const SparseMatrix A = random_spd(400, 3, 5);
  const Eigen::VectorXd b = random_vector(400, 2);
  SkylineFactorization sky;
  sky.factorize(A);  // analyzes on first use
  const Eigen::VectorXd x = sky.solve(b);
  EXPECT_LT(relative_difference(x, Eigen::MatrixXd(A).ldlt().solve(b)), 1e-10);
  CholmodFactorization chol;
  chol.factorize(A);
  EXPECT_LT(relative_difference(x, chol.solve(b)), 1e-10);
}

TEST(SkylineTest, SaddlePointWithTrailingMultipliersMatchesDenseSolve) {
  const int n = 20 * 15, m = 12;
  const SparseMatrix A = saddle_point(20, 15, m, 9);
  const Eigen::VectorXd b = random_vector(n + m, 3);
  SkylineFactorization sky(m);
  sky.analyze(A);
  for (int r = 0; r < m; ++r) EXPECT_EQ(sky.permutation()[n + r], n + r);
  sky.factorize(A);
  const Eigen::VectorXd x = sky.solve(b);
  const Eigen::MatrixXd dense(A);
  // The matrix is indefinite: the reference is a dense LU with full pivoting (and the pivoted dense LDL^T).
  const Eigen::VectorXd ref = dense.fullPivLu().solve(b);
  EXPECT_LT(relative_difference(x, ref), 1e-10);
  EXPECT_LT(relative_difference(dense.ldlt().solve(b), ref), 1e-8);
  EXPECT_LT((A * x - b).norm() / b.norm(), 1e-12);
  EXPECT_EQ(sky.counted_flops(), sky.stats().flops);
}

TEST(SkylineTest, CountedFlopsEqualPredictedFlops) {
  for (const SparseMatrix& A : {grid_laplacian(30, 20, 1.0), random_spd(300, 4, 8), saddle_point(12, 10, 6, 4)}) {
    SkylineFactorization sky(A.rows() == 126 ? 6 : 0);
    sky.analyze(A);
    const double predicted = sky.stats().flops;
    EXPECT_EQ(predicted, flops_from_profile(skyline_first_rows(A, sky.permutation())));
    sky.factorize(A);
    EXPECT_EQ(sky.counted_flops(), predicted);
    EXPECT_GT(predicted, 0.0);
  }
}

TEST(SkylineTest, FlopFormulaOnFullAndTridiagonalProfiles) {
  const int n = 40;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Random(n, n);
  dense = dense * dense.transpose() + n * Eigen::MatrixXd::Identity(n, n);
  const SparseMatrix full = dense.sparseView();
  SkylineFactorization sky;
  sky.factorize(full);
  // sum_j sum_{i<j} (2 i + 3) = sum_j (j^2 + 2 j), about n^3 / 3
  const double expected = (n - 1.0) * n * (2.0 * n - 1.0) / 6.0 + n * (n - 1.0);
  EXPECT_EQ(sky.stats().flops, expected);
  EXPECT_EQ(sky.counted_flops(), expected);
  EXPECT_LT(relative_difference(sky.solve(dense.col(0)), Eigen::VectorXd::Unit(n, 0)), 1e-12);
  SkylineFactorization tri;
  tri.factorize(grid_laplacian(50, 1, 0.0));  // a path: one division and one update per column
  EXPECT_EQ(tri.stats().flops, 3.0 * 49);
  EXPECT_EQ(tri.stats().nnz_factor, 99.0);
}

TEST(SkylineTest, RefactorizationWithNewValuesReusesTheAnalysis) {
  SkylineFactorization sky;
  sky.analyze(grid_laplacian(15, 10, 1.0));
  const std::vector<int> perm = sky.permutation();
  const Eigen::VectorXd b = random_vector(150, 4);
  for (double shift : {1.0, 2.5}) {
    const SparseMatrix A = grid_laplacian(15, 10, shift);
    sky.factorize(A);
    EXPECT_LT(relative_difference(sky.solve(b), Eigen::MatrixXd(A).llt().solve(b)), 1e-10);
  }
  EXPECT_EQ(sky.permutation(), perm);
  EXPECT_EQ(sky.stats().factorizations, 2);
}

TEST(SkylineTest, ZeroRowAndColumnThrowsWithItsOriginalIndex) {
  SparseMatrix A = grid_laplacian(30, 20, 1.0);
  const int dead = 137;
  for (int c = 0; c < A.cols(); ++c)
    for (SparseMatrix::InnerIterator it(A, c); it; ++it)
      if (it.row() == dead || c == dead) it.valueRef() = 0.0;
  SkylineFactorization sky;
  sky.analyze(A);
  try {
    sky.factorize(A);
    FAIL() << "expected SingularMatrix";
  } catch (const SingularMatrix& e) {
    EXPECT_EQ(e.column, dead);
    EXPECT_NE(std::string(e.what()).find("non-positive pivot 0 "), std::string::npos) << e.what();
  }
  EXPECT_THROW(sky.solve(Eigen::VectorXd::Ones(600)), std::logic_error);
}

TEST(SkylineTest, NeumannLaplacianIsSingular) {
  // Graph Laplacian (rows sum to zero): its last pivot vanishes up to rounding.
  SparseMatrix A = grid_laplacian(30, 20, 0.0);
  for (int c = 0; c < A.cols(); ++c) A.coeffRef(c, c) = -(A.col(c).sum() - A.coeff(c, c));
  SkylineFactorization sky;
  try {
    sky.factorize(A);
    FAIL() << "expected SingularMatrix";
  } catch (const SingularMatrix& e) {
    EXPECT_GE(e.column, 0);
    EXPECT_LT(e.column, 600);
  }
}

TEST(SkylineTest, BrickGraphWithThreeDofsPerNodeMatchesCholmod) {
  // Node graph of an 8x8x8 hexahedral mesh (27-point couplings), 3 dofs per node, SPD values.
  const int e = 8, p = e + 1, nodes = p * p * p;
  Eigen::Matrix3d block;
  block << 2.0, 0.5, 0.3, 0.5, 2.0, 0.4, 0.3, 0.4, 2.0;
  Triplets t;
  for (int v = 0; v < nodes; ++v) {
    const int x = v % p, y = (v / p) % p, z = v / (p * p);
    int neighbours = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int X = x + dx, Y = y + dy, Z = z + dz;
          if ((dx || dy || dz) && X >= 0 && Y >= 0 && Z >= 0 && X < p && Y < p && Z < p) {
            const int w = X + p * (Y + p * Z);
            ++neighbours;
            for (int a = 0; a < 3; ++a)
              for (int c = 0; c < 3; ++c) t.emplace_back(3 * v + a, 3 * w + c, -block(a, c));
          }
        }
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) t.emplace_back(3 * v + a, 3 * v + c, (neighbours + 0.5) * block(a, c));
  }
  const SparseMatrix A = from_triplets(3 * nodes, t);
  const Eigen::VectorXd b = random_vector(3 * nodes, 6);
  SkylineFactorization sky;
  sky.factorize(A);
  CholmodFactorization chol;
  chol.factorize(A);
  EXPECT_LT(relative_difference(sky.solve(b), chol.solve(b)), 1e-10);
  EXPECT_EQ(sky.counted_flops(), sky.stats().flops);
  std::cout << "[ skyline ] n=" << A.rows() << " nnz(A)=" << A.nonZeros() << " profile=" << sky.stats().nnz_factor
            << " flops=" << sky.stats().flops << " analyze=" << sky.stats().analyze_s
            << "s factorize=" << sky.stats().factorize_s << "s | cholmod " << chol.stats().ordering
            << " nnz(L)=" << chol.stats().nnz_factor << " flops=" << chol.stats().flops << '\n';
}

TEST(SkylineFactoryTest, MakesByNameAndRejectsUnknownNames) {
  EXPECT_NE(dynamic_cast<SkylineFactorization*>(make_factorization("skyline").get()), nullptr);
  EXPECT_NE(dynamic_cast<CholmodFactorization*>(make_factorization("cholmod").get()), nullptr);
  EXPECT_THROW(make_factorization("nope"), std::invalid_argument);
  try {
    make_factorization("nope");
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("skyline"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cholmod"), std::string::npos);
  }
}

}  // namespace
}  // namespace rollsim::test_skyline
