// Tests of CholmodFactorization's settings: every ordering and amalgamation gives the solution of a dense Cholesky
// (the factorization changes, the answer must not); rollsim's default orders on the node graph in 3D and by AMD in 2D;
// an unknown ordering is refused.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "grid_matrix.h"
#include "solve/CholmodFactorization.h"

namespace rollsim::test_cholmod_factorization {
namespace {

using testing::fe_grid_matrix;

void expect_dense_solution(const SparseMatrix& A, const CholmodSettings& settings, const std::string& what) {
  CholmodFactorization chol(settings);
  chol.analyze(A);
  chol.factorize(A);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  const Eigen::VectorXd ref = Eigen::LLT<Eigen::MatrixXd>(Eigen::MatrixXd(A)).solve(b);
  EXPECT_LT((chol.solve(b) - ref).norm() / ref.norm(), 1e-12) << what;
  EXPECT_GT(chol.stats().flops, 0) << what;
}

TEST(CholmodFactorization, EveryOrderingAndAmalgamationSolvesAlike) {
  const SparseMatrix cube = fe_grid_matrix(6, 3, 3, 11, 13), square = fe_grid_matrix(14, 2, 2, 12, 9);
  for (const std::string ordering : {"auto", "automatic", "amd", "metis", "nesdis", "nodes"})
    for (const auto& relax : std::vector<std::vector<int>>{{4, 16, 48}, {8, 32, 96}, {0, 0, 0}}) {
      CholmodSettings s;
      s.ordering = ordering;
      for (int i = 0; i < 3; ++i) s.nrelax[i] = relax[static_cast<size_t>(i)];
      const std::string what = ordering + " nrelax " + std::to_string(relax[0]);
      expect_dense_solution(cube, s, "3D " + what);
      expect_dense_solution(square, s, "2D " + what);
    }
}

TEST(CholmodFactorization, DefaultOrdersTheNodeGraphIn3DAndByAmdIn2D) {
  CholmodFactorization cube;
  cube.analyze(fe_grid_matrix(4, 3, 3, 13));
  EXPECT_EQ(cube.stats().ordering, "METIS-nodes");
  CholmodFactorization square;
  square.analyze(fe_grid_matrix(8, 2, 2, 13));
  EXPECT_EQ(square.stats().ordering, "AMD");
  CholmodSettings nodes;
  nodes.ordering = "nodes";
  CholmodFactorization forced(nodes);
  forced.analyze(fe_grid_matrix(8, 2, 2, 13));
  EXPECT_EQ(forced.stats().ordering, "METIS-nodes");
  CholmodFactorization theirs(CholmodSettings::cholmod_defaults());
  theirs.analyze(fe_grid_matrix(4, 2, 2, 13));
  EXPECT_EQ(theirs.stats().ordering, "AMD");  // CHOLMOD's own choice for a small 2D matrix
}

TEST(CholmodFactorization, RefusesAnUnknownOrdering) {
  CholmodSettings s;
  s.ordering = "random";
  EXPECT_THROW(CholmodFactorization{s}, std::invalid_argument);
}

}  // namespace
}  // namespace rollsim::test_cholmod_factorization
