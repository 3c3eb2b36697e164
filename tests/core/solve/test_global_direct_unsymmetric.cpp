// `direct` factors the bordered system with C_eqᵀ in the groups' equations and C in the constraint rows (slipping
// Coulomb friction makes them differ): its solution is the dense solve's, and a new C_eq alone is a new matrix.
#include <gtest/gtest.h>

#include "solve/SolverStrategy.h"

namespace test_global_direct_unsymmetric {

using namespace rollsim;

namespace {
SparseMatrix sparse(const Eigen::MatrixXd& A) { return A.sparseView(); }

BlockSystem system_with(const Eigen::MatrixXd& C_eq) {
  Group g;
  g.name = "body";
  Eigen::MatrixXd K(3, 3);
  K << 4, -1, 0, -1, 4, -1, 0, -1, 4;
  g.K = sparse(K);
  g.f = Eigen::Vector3d(1, 2, 3);
  g.C = sparse(Eigen::RowVector3d(1, 0, -1));
  g.C_eq = sparse(C_eq);
  g.R.resize(3, 0);
  BlockSystem sys;
  sys.groups.push_back(g);
  sys.d = Eigen::VectorXd::Constant(1, 0.5);
  return sys;
}

Eigen::VectorXd dense_solve(const BlockSystem& sys) {
  const Group& g = sys.groups[0];
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 4);
  A.topLeftCorner(3, 3) = Eigen::MatrixXd(g.K);
  A.topRightCorner(3, 1) = Eigen::MatrixXd(g.equation_C()).transpose();
  A.bottomLeftCorner(1, 3) = Eigen::MatrixXd(g.C);
  Eigen::VectorXd f(4);
  f << g.f, sys.d;
  return A.partialPivLu().solve(f);
}
}  // namespace

TEST(GlobalDirectUnsymmetric, SolvesTheBorderedSystemWithCeqInTheEquations) {
  auto direct = make_solver("direct", {});
  ASSERT_TRUE(direct->solves_unsymmetric());
  EXPECT_FALSE(make_solver("skyline", {})->solves_unsymmetric());
  for (const Eigen::RowVector3d& ceq : {Eigen::RowVector3d(1, 0.3, -1), Eigen::RowVector3d(1, -0.3, -1)}) {
    const BlockSystem sys = system_with(ceq);  // the second: only C_eq changed — the factor must follow it
    const BlockSolution s = direct->solve(sys);
    const Eigen::VectorXd x = dense_solve(sys);
    EXPECT_LT((s.u[0] - x.head(3)).norm(), 1e-12);
    EXPECT_NEAR(s.lambda[0], x[3], 1e-12);
  }
  EXPECT_EQ(direct->stats().factorizations.at("body"), 2);
}

// `mixed` with the `dense` interface solver forms F = C K⁻¹ C_eqᵀ, unsymmetric, and gives the same solution.
TEST(GlobalDirectUnsymmetric, MixedWithTheDenseInterfaceGivesTheSameSolution) {
  SolverOptions o;
  o.interface_solver = InterfaceSolver::Dense;
  const BlockSystem sys = system_with(Eigen::RowVector3d(1, 0.3, -1));
  const BlockSolution s = make_solver("mixed", o)->solve(sys);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  const Eigen::VectorXd x = dense_solve(sys);
  EXPECT_LT((s.u[0] - x.head(3)).norm(), 1e-12);
  EXPECT_NEAR(s.lambda[0], x[3], 1e-12);
}

}  // namespace test_global_direct_unsymmetric
