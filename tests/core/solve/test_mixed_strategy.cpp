// `feti` on subdomains whose own tangents are indefinite while the whole system's is positive definite (a compressed
// finite-strain subdomain, paper Example 5): a spring chain 0-1-…-6, node 0 held, a unit force at node 6, torn at
// nodes 4 and 5. The spring 4-5 (total stiffness 1) is split between the subdomains as +1.5 (A) and −0.5 (B), so B —
// nodes 4, 5, 6, floating — has a negative eigenvalue beside its translation. Every spring carries the force 1:
// u_i = i. Before CholeskyOrLU, CHOLMOD refused B's tangent and the solve threw.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "solve/CholmodFactorization.h"
#include "solve/MixedStrategy.h"

namespace test_mixed_strategy {

using namespace rollsim;

namespace {
using Triplets = std::vector<Eigen::Triplet<double, int>>;

/// A spring k between local dofs a and b (−1: a held node).
void spring(Triplets& t, int a, int b, double k) {
  if (a >= 0) t.emplace_back(a, a, k);
  if (b >= 0) t.emplace_back(b, b, k);
  if (a >= 0 && b >= 0) t.emplace_back(a, b, -k), t.emplace_back(b, a, -k);
}

SparseMatrix matrix(int rows, int cols, const Triplets& t) {
  SparseMatrix A(rows, cols);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

BlockSystem torn_chain(double split_a, double split_b) {
  Group a;  // nodes 1..5 (dofs 0..4), node 0 held
  a.name = "A";
  Triplets ka;
  spring(ka, -1, 0, 1), spring(ka, 0, 1, 1), spring(ka, 1, 2, 1), spring(ka, 2, 3, 1), spring(ka, 3, 4, split_a);
  a.K = matrix(5, 5, ka);
  a.f = Eigen::VectorXd::Zero(5);
  a.C = matrix(2, 5, {{0, 3, 1.0}, {1, 4, 1.0}});  // u_A(4) − u_B(4) = 0, u_A(5) − u_B(5) = 0
  a.R.resize(5, 0);
  Group b;  // nodes 4, 5, 6 (dofs 0..2), floating
  b.name = "B";
  Triplets kb;
  spring(kb, 0, 1, split_b), spring(kb, 1, 2, 1);
  b.K = matrix(3, 3, kb);
  b.f = Eigen::Vector3d(0, 0, 1);
  b.C = matrix(2, 3, {{0, 0, -1.0}, {1, 1, -1.0}});
  b.R = Eigen::MatrixXd::Ones(3, 1);
  BlockSystem sys;
  sys.groups = {a, b};
  sys.d = Eigen::VectorXd::Zero(2);
  ConstraintBlock glue;
  glue.kind = ConstraintKind::Glue;
  glue.begin = 0, glue.end = 2;
  sys.blocks.push_back(glue);
  return sys;
}

/// A lattice of scalar springs on a (2m + 1) × (ny + 1) grid (column 0 held, loads on the last column varying along
/// it), torn at column m into A (columns 1..m) and B (columns m..2m, floating: its kernel is the constants). Springs
/// along x are 1; along y, 1 in A, `along_y` in B's columns m + 1..2m, and the interface column's are split half and
/// half. A negative `along_y` makes B alone indefinite beside its kernel (a mode constant along x and alternating along
/// y has negative energy), and its interior block too. ny + 1 multipliers: enough for a preconditioner to show.
BlockSystem torn_lattice(int m, int ny, double along_y) {
  const int rows = ny + 1;
  auto dof = [&](int i, int first) { return (i - first) * rows; };  // + j
  Group a, b;
  a.name = "A", b.name = "B";
  Triplets ka, kb;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < 2 * m; ++i) {  // springs along x: (i, j)–(i + 1, j)
      if (i < m) spring(ka, i == 0 ? -1 : dof(i, 1) + j, dof(i + 1, 1) + j, 1);
      if (i >= m) spring(kb, dof(i, m) + j, dof(i + 1, m) + j, 1);
    }
    if (j == ny) continue;
    for (int i = 1; i <= 2 * m; ++i) {  // springs along y: (i, j)–(i, j + 1)
      if (i <= m) spring(ka, dof(i, 1) + j, dof(i, 1) + j + 1, i == m ? 0.5 : 1);
      if (i >= m) spring(kb, dof(i, m) + j, dof(i, m) + j + 1, i == m ? 0.5 : along_y);
    }
  }
  const int na = m * rows, nb = (m + 1) * rows;
  a.K = matrix(na, na, ka), b.K = matrix(nb, nb, kb);
  a.f = Eigen::VectorXd::Zero(na), b.f = Eigen::VectorXd::Zero(nb);
  for (int j = 0; j < rows; ++j) b.f[dof(2 * m, m) + j] = 1.0 + std::sin(0.7 * j);
  Triplets ca, cb;
  for (int j = 0; j < rows; ++j) ca.emplace_back(j, dof(m, 1) + j, 1.0), cb.emplace_back(j, dof(m, m) + j, -1.0);
  a.C = matrix(rows, na, ca), b.C = matrix(rows, nb, cb);
  a.R.resize(na, 0);
  b.R = Eigen::MatrixXd::Ones(nb, 1);
  BlockSystem sys;
  sys.groups = {a, b};
  sys.d = Eigen::VectorXd::Zero(rows);
  ConstraintBlock glue;
  glue.kind = ConstraintKind::Glue;
  glue.begin = 0, glue.end = rows;
  sys.blocks.push_back(glue);
  return sys;
}

void expect_u_equals_node_index(const BlockSolution& s, double tol) {
  EXPECT_LT((s.u[0] - Eigen::VectorXd::LinSpaced(5, 1, 5)).norm(), tol);
  EXPECT_LT((s.u[1] - Eigen::Vector3d(4, 5, 6)).norm(), tol);
}
}  // namespace

TEST(MixedStrategy, FetiSolvesSubdomainsWithIndefiniteTangentsAsDirect) {
  const BlockSystem sys = torn_chain(1.5, -0.5);
  ASSERT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(sys.groups[1].K)).eigenvalues()[0], -0.1)
      << "B alone must be indefinite";
  CholmodFactorization llt;  // what GroupSolver factored with before: it refuses B without its fixed dof
  const SparseMatrix Kpp = sys.groups[1].K.bottomRightCorner(2, 2);
  EXPECT_THROW(llt.factorize(Kpp), NotPositiveDefinite);
  const BlockSolution direct = make_solver("direct", {})->solve(sys);
  expect_u_equals_node_index(direct, 1e-10);
  SolverOptions o;
  o.cg_tolerance = 1e-12;
  for (const std::string preconditioner : {"none", "lumped"}) {
    SCOPED_TRACE(preconditioner);
    o.preconditioner = from_word<Preconditioner>(preconditioner);
    MixedStrategy feti(o, /*subdomains=*/true);
    const BlockSolution s = feti.solve(sys);
    EXPECT_TRUE(s.status.ok()) << s.status.message;
    expect_u_equals_node_index(s, 1e-9);
    EXPECT_LT((s.lambda - direct.lambda).norm(), 1e-9);
    EXPECT_EQ(feti.gmres_solves(), 1) << "an indefinite subdomain factor: the interface by GMRES";
  }
}

TEST(MixedStrategy, FetiKeepsCGForPositiveDefiniteSubdomains) {
  const BlockSystem sys = torn_chain(0.5, 0.5);  // the same chain, B positive semi-definite
  SolverOptions o;
  o.cg_tolerance = 1e-12;
  MixedStrategy feti(o, /*subdomains=*/true);
  const BlockSolution s = feti.solve(sys);
  EXPECT_TRUE(s.status.ok()) << s.status.message;
  expect_u_equals_node_index(s, 1e-9);
  EXPECT_EQ(feti.gmres_solves(), 0);
}

// The interface preconditioners work through projected GMRES when a subdomain is indefinite (right preconditioning,
// Π M⁻¹), Dirichlet's K_ii factored by CholeskyOrLU (B's interior block is indefinite too: CHOLMOD refused it): each
// gives direct's answer; lumped takes fewer iterations than none, Dirichlet a third fewer.
TEST(MixedStrategy, PreconditionersCutGMRESIterationsOnAnIndefiniteSubdomain) {
  const BlockSystem sys = torn_lattice(8, 32, -0.01);
  const Eigen::MatrixXd KB(sys.groups[1].K);
  ASSERT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(KB).eigenvalues()[0], -1e-3) << "B alone must be indefinite";
  const BlockSolution direct = make_solver("direct", {})->solve(sys);
  SolverOptions o;
  o.cg_tolerance = 1e-10;
  std::map<std::string, int> iterations;
  for (const std::string preconditioner : {"none", "lumped", "dirichlet"}) {
    SCOPED_TRACE(preconditioner);
    o.preconditioner = from_word<Preconditioner>(preconditioner);
    MixedStrategy feti(o, /*subdomains=*/true);
    const BlockSolution s = feti.solve(sys);
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    EXPECT_EQ(feti.gmres_solves(), 1);
    EXPECT_LT((s.lambda - direct.lambda).norm(), 1e-8 * direct.lambda.norm());
    EXPECT_LT((s.u[1] - direct.u[1]).norm(), 1e-8 * direct.u[1].norm());
    iterations[preconditioner] = feti.last_interface_solve().iterations;
  }
  EXPECT_LT(iterations["lumped"], iterations["none"]);
  EXPECT_LT(4 * iterations["dirichlet"], 3 * iterations["none"]);
}

// The `dense` interface solver (F formed from the groups' flexibilities, factored by LU) gives direct's answer where
// the Krylov solvers do: an indefinite floating subdomain (GMRES's case) and a positive definite one, with no
// interface iterations; a second solve with the same factors forms nothing again.
TEST(MixedStrategy, DenseInterfaceSolverGivesDirectsAnswer) {
  SolverOptions o;
  o.interface_solver = InterfaceSolver::Dense;
  for (const BlockSystem& sys : {torn_chain(1.5, -0.5), torn_chain(0.5, 0.5), torn_lattice(8, 32, -0.01)}) {
    const BlockSolution direct = make_solver("direct", {})->solve(sys);
    MixedStrategy feti(o, /*subdomains=*/true);
    const BlockSolution s = feti.solve(sys);
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    for (size_t g = 0; g < 2; ++g) EXPECT_LT((s.u[g] - direct.u[g]).norm(), 1e-10 * direct.u[g].norm());
    EXPECT_LT((s.lambda - direct.lambda).norm(), 1e-10 * direct.lambda.norm());
    EXPECT_EQ(feti.stats().cg_iterations, 0);
    EXPECT_EQ(feti.gmres_solves(), 0);
    EXPECT_LT(feti.last_interface_solve().residuals.back(), 1e-12);
  }
}

// A floating subdomain that no constraint holds (its glue rows cut off) makes the bordered interface singular: the
// dense solver reports it as a breakdown naming its residual, never NaN as an answer.
TEST(MixedStrategy, DenseInterfaceSolverReportsASingularInterface) {
  BlockSystem sys = torn_chain(0.5, 0.5);
  sys.groups[1].C = SparseMatrix(2, 3);  // B no longer glued: its translation is free, its load unbalanced
  SolverOptions o;
  o.interface_solver = InterfaceSolver::Dense;
  MixedStrategy feti(o, /*subdomains=*/true);
  const BlockSolution s = feti.solve(sys);
  EXPECT_FALSE(s.status.ok());
  EXPECT_EQ(s.status.reason, Reason::breakdown);
  EXPECT_NE(s.status.message.find("the dense interface solve left a relative residual"), std::string::npos)
      << s.status.message;
}

}  // namespace test_mixed_strategy
