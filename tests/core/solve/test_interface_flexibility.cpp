// InterfaceFlexibility forms a group's part of the interface operator, F_g = C K⁺ C_eqᵀ, from K⁺'s columns at the
// dofs the constraints touch: it must equal the operator the Krylov solvers apply (GroupSolver::apply column by
// column), for a regular and a floating group (K⁺ with a fixed dof) and with C_eq ≠ C; and while the factor stays
// (the same Group::version) only dofs that newly enter the constraints are solved for.
#include <gtest/gtest.h>

#include "grid_matrix.h"
#include "solve/InterfaceFlexibility.h"

namespace test_interface_flexibility {

using namespace rollsim;

namespace {
using Triplets = std::vector<Eigen::Triplet<double, int>>;

/// Rows that touch the dofs `first`, first + step, … (three per row, weights varying).
SparseMatrix rows_on(int rows, int n, int first, int step) {
  Triplets t;
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < 3; ++k) t.emplace_back(r, (first + (3 * r + k) * step) % n, 1.0 + 0.1 * r - 0.3 * k);
  SparseMatrix C(rows, n);
  C.setFromTriplets(t.begin(), t.end());
  return C;
}

Group regular_group() {
  Group g;
  g.name = "regular";
  g.K = rollsim::testing::fe_grid_matrix(5, 2, 2, 11);
  g.R.resize(g.K.rows(), 0);
  g.C = rows_on(4, static_cast<int>(g.K.rows()), 3, 5);
  return g;
}

/// A chain of springs, free at both ends: its kernel is the constants, so K⁺ fixes one dof.
Group floating_group(int n) {
  Group g;
  g.name = "floating";
  Triplets t;
  for (int i = 0; i + 1 < n; ++i) {
    const double k = 1.0 + 0.05 * i;
    t.emplace_back(i, i, k), t.emplace_back(i + 1, i + 1, k), t.emplace_back(i, i + 1, -k),
        t.emplace_back(i + 1, i, -k);
  }
  g.K.resize(n, n);
  g.K.setFromTriplets(t.begin(), t.end());
  g.R = Eigen::MatrixXd::Ones(n, 1);
  g.C = rows_on(3, n, 1, 2);
  return g;
}

/// C K⁺ C_eqᵀ with K⁺ applied one column at a time, as the interface CG applies it.
Eigen::MatrixXd by_columns(const Group& g, GroupSolver& solver) {
  const Eigen::MatrixXd CeqT = Eigen::MatrixXd(g.equation_C()).transpose();
  Eigen::MatrixXd KC(CeqT.rows(), CeqT.cols());
  for (Eigen::Index j = 0; j < CeqT.cols(); ++j) KC.col(j) = solver.apply(CeqT.col(j));
  return g.C * KC;
}

void expect_equal(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const char* what) {
  ASSERT_EQ(a.rows(), b.rows()) << what;
  ASSERT_EQ(a.cols(), b.cols()) << what;
  EXPECT_LT((a - b).norm(), 1e-12 * b.norm()) << what;
}
}  // namespace

TEST(InterfaceFlexibility, EqualsTheOperatorTheKrylovSolversApply) {
  for (Group g : {regular_group(), floating_group(30)}) {
    SCOPED_TRACE(g.name);
    GroupSolver solver("cholmod");
    solver.factorize(g);
    InterfaceFlexibility flex;
    expect_equal(flex.interface_block(g, solver), by_columns(g, solver), "C = C_eq");
    g.C_eq = g.C;
    g.C_eq.coeffs() *= 0.5;
    g.C_eq.coeffRef(0, g.C_eq.cols() - 1) = 0.25;  // a dof only C_eq touches (slipping friction's rows differ)
    expect_equal(flex.interface_block(g, solver), by_columns(g, solver), "C_eq ≠ C");
  }
}

TEST(InterfaceFlexibility, SolvesOnlyForDofsThatEnterWhileTheFactorStays) {
  Group g = regular_group();
  GroupSolver solver("cholmod");
  solver.factorize(g);
  InterfaceFlexibility flex;
  flex.interface_block(g, solver);
  const long first = flex.columns_solved();
  EXPECT_EQ(first, 12) << "4 rows of 3 distinct dofs";
  g.C = rows_on(5, static_cast<int>(g.K.rows()), 3, 5);  // one more row: three more dofs
  expect_equal(flex.interface_block(g, solver), by_columns(g, solver), "a row more");
  EXPECT_EQ(flex.columns_solved(), first + 3);
  g.K.coeffs() *= 2.0;  // a new tangent: everything again
  ++g.version;
  solver.factorize(g);
  expect_equal(flex.interface_block(g, solver), by_columns(g, solver), "new factor");
  EXPECT_EQ(flex.columns_solved(), first + 3 + 15);
}

}  // namespace test_interface_flexibility
