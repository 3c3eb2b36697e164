// Tests of supernodal_solve (our triangular solves with a CHOLMOD supernodal factor) against CHOLMOD's own
// cholmod_solve and a dense Cholesky: 2D grids (small supernodes) and a 3D brick (large ones with rows below the
// diagonal block, the gemv / gather path), a 1×1 matrix, many right-hand sides through one scratch vector; and
// CholmodFactorization's block of right-hand sides (solve_columns, through cholmod_solve) against its vector solves.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "solve/CholmodFactorization.h"
#include "solve/CholmodView.h"
#include "solve/SupernodalSolve.h"

namespace rollsim::test_supernodal_solve {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

/// Q1 node graph of an n^dim grid (all neighbours within one cell), `dofs` per node, SPD by diagonal dominance.
SparseMatrix grid_matrix(int n, int dim, int dofs, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 0.0);
  const int p = n + 1, nodes = dim == 2 ? p * p : p * p * p;
  auto coord = [&](int v, int k) { return k == 0 ? v % p : k == 1 ? (v / p) % p : v / (p * p); };
  Triplets t;
  std::vector<double> row_sum(static_cast<size_t>(nodes * dofs), 0.0);
  for (int v = 0; v < nodes; ++v)
    for (int w = v + 1; w < nodes; ++w) {
      bool near = true;
      for (int k = 0; k < dim; ++k) near = near && std::abs(coord(v, k) - coord(w, k)) <= 1;
      if (!near) continue;
      for (int a = 0; a < dofs; ++a)
        for (int c = 0; c < dofs; ++c) {
          const double x = value(rng);
          t.emplace_back(v * dofs + a, w * dofs + c, x);
          t.emplace_back(w * dofs + c, v * dofs + a, x);
          row_sum[static_cast<size_t>(v * dofs + a)] += -x;
          row_sum[static_cast<size_t>(w * dofs + c)] += -x;
        }
    }
  for (int i = 0; i < nodes * dofs; ++i) t.emplace_back(i, i, row_sum[static_cast<size_t>(i)] + 0.1);
  SparseMatrix A(nodes * dofs, nodes * dofs);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// CHOLMOD's own analysis, factorization and solve, for reference.
Eigen::VectorXd solve_with_cholmod(const SparseMatrix& A, const Eigen::VectorXd& b, cholmod_common& c,
                                   cholmod_factor*& L) {
  cholmod_sparse s = cholmod_view(A);
  L = cholmod_analyze(&s, &c);
  cholmod_factorize(&s, L, &c);
  return cholmod_solve_vector(*L, b, c);
}

void expect_equal_to_cholmod_and_dense(const SparseMatrix& A, const char* what) {
  cholmod_common c;
  cholmod_start(&c);
  c.supernodal = CHOLMOD_SUPERNODAL;
  c.final_ll = 1;
  cholmod_factor* L = nullptr;
  Eigen::VectorXd work;
  const Eigen::LLT<Eigen::MatrixXd> dense{Eigen::MatrixXd(A)};
  for (unsigned k = 0; k < 3; ++k) {  // several right-hand sides through the same scratch vector
    const Eigen::VectorXd b = Eigen::VectorXd::Random(A.rows()) + Eigen::VectorXd::Constant(A.rows(), k);
    if (L) cholmod_free_factor(&L, &c);
    const Eigen::VectorXd ref = solve_with_cholmod(A, b, c, L);
    ASSERT_TRUE(L->is_super) << what;
    const Eigen::VectorXd x = supernodal_solve(*L, b, work);
    EXPECT_LT((x - ref).norm() / ref.norm(), 1e-12) << what << ": vs cholmod_solve";
    EXPECT_LT((x - dense.solve(b)).norm() / ref.norm(), 1e-10) << what << ": vs dense LLᵀ";
  }
  EXPECT_GT(L->nsuper, 1u) << what;
  cholmod_free_factor(&L, &c);
  cholmod_finish(&c);
}

TEST(SupernodalSolve, TwoDimensionalGridWithSmallSupernodes) {
  expect_equal_to_cholmod_and_dense(grid_matrix(20, 2, 2, 1), "2D 20×20, 2 dofs per node");
}

TEST(SupernodalSolve, ThreeDimensionalBrickWithLargeSupernodes) {
  expect_equal_to_cholmod_and_dense(grid_matrix(7, 3, 3, 2), "3D 7×7×7, 3 dofs per node");
}

TEST(SupernodalSolve, ManyColumnsAtOnceEqualOneAtATime) {
  const SparseMatrix A = grid_matrix(6, 3, 3, 4);
  CholmodFactorization chol;
  chol.factorize(A);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 7);
  const Eigen::MatrixXd X = chol.solve_columns(B);
  ASSERT_EQ(X.rows(), A.rows());
  ASSERT_EQ(X.cols(), 7);
  for (Eigen::Index j = 0; j < B.cols(); ++j)
    EXPECT_LT((X.col(j) - chol.solve(B.col(j))).norm() / X.col(j).norm(), 1e-13) << "column " << j;
  EXPECT_LT((A * X - B).norm() / B.norm(), 1e-12);
}

TEST(SupernodalSolve, CholmodFactorizationSolvesWithIt) {
  const SparseMatrix A = grid_matrix(6, 3, 3, 3);
  CholmodFactorization chol;
  EXPECT_THROW(chol.solve(Eigen::VectorXd::Ones(A.rows())), std::runtime_error) << "no factor yet";
  chol.factorize(A);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(A.rows());
  EXPECT_LT((A * chol.solve(b) - b).norm() / b.norm(), 1e-12);
  SparseMatrix one(1, 1);
  one.insert(0, 0) = 4.0;
  one.makeCompressed();
  CholmodFactorization scalar;
  scalar.factorize(one);
  EXPECT_DOUBLE_EQ(scalar.solve(Eigen::VectorXd::Constant(1, 2.0))[0], 0.5);
}

TEST(SupernodalSolve, InverseQuadraticOverTheColumnsReachesEqualsTheDenseOne) {
  // unit columns on one face of a 3D brick (a flexibility's surface dofs: their reaches start near the leaves of the
  // nested dissection), a column of several nonzeros in different subtrees, and a zero column (a fixed dof)
  const SparseMatrix A = grid_matrix(7, 3, 3, 5);
  CholmodFactorization chol;
  chol.factorize(A);
  std::vector<int> face;
  for (int v = 0; v < 8 * 8; ++v) face.push_back(3 * v + v % 3);  // z = 0: nodes 0..63, one dof each
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(A.rows(), static_cast<Eigen::Index>(face.size()) + 2);
  for (size_t j = 0; j < face.size(); ++j) E(face[j], static_cast<Eigen::Index>(j)) = 1.0;
  E(5, static_cast<Eigen::Index>(face.size())) = 0.5, E(A.rows() - 4, static_cast<Eigen::Index>(face.size())) = -2.0;
  const Eigen::MatrixXd Phi = chol.inverse_quadratic(E);
  const Eigen::MatrixXd ref = E.transpose() * Eigen::LLT<Eigen::MatrixXd>(Eigen::MatrixXd(A)).solve(E);
  ASSERT_EQ(Phi.rows(), E.cols());
  EXPECT_LT((Phi - ref).norm() / ref.norm(), 1e-12);
  EXPECT_EQ(Phi.col(E.cols() - 1).norm(), 0.0) << "a zero column stays zero";
  EXPECT_LT((Phi - Phi.transpose()).norm(), 1e-14 * Phi.norm());
}

}  // namespace
}  // namespace rollsim::test_supernodal_solve
