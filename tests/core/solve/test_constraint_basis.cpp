// The independent rows of a constraint block and the null space of Cᵀ: four rows on three dofs (the 3D pass's stick
// rows of slave nodes on a symmetry plane, holding only roll dofs) keep three, and the fourth's combination of the
// others spans ker Cᵀ; the least-norm λ has no part there and the same forces Cᵀλ.
#include <gtest/gtest.h>

#include "solve/ConstraintBasis.h"

namespace test_constraint_basis {

using namespace rollsim;

namespace {
SparseMatrix rows_on_three_dofs() {
  Eigen::MatrixXd C(5, 4);
  C << -0.005, -0.995, 0, 0,  //
      -0.67, -0.33, 0, 0,     //
      0, -0.66, -0.34, 0,     //
      0, 0, -1, 0,            //
      1, 0, 0, 1;             // a row with a dof of its own
  return C.sparseView();
}
}  // namespace

TEST(ConstraintBasis, FullRowRankKeepsEveryRow) {
  Eigen::MatrixXd C(2, 3);
  C << 1, 0, -1, 0, 1, 1;
  const ConstraintBasis b = independent_rows(C.sparseView());
  EXPECT_EQ(b.kept, (std::vector<int>{0, 1}));
  EXPECT_TRUE(b.full_rank());
  const Eigen::Vector2d lambda(3, -4);
  EXPECT_EQ(b.minimum_norm(lambda), lambda);
}

TEST(ConstraintBasis, DependentRowsLeaveANullSpaceOfCt) {
  const SparseMatrix C = rows_on_three_dofs();
  const ConstraintBasis b = independent_rows(C);
  ASSERT_EQ(b.kept.size(), 4u);  // one of the four rows on three dofs goes
  EXPECT_EQ(b.null_space.cols(), 1);
  EXPECT_LT((C.transpose() * b.null_space).norm(), 1e-12);
  EXPECT_GT(b.null_space.norm(), 0.5);
  EXPECT_EQ(std::count(b.kept.begin(), b.kept.end(), 4), 1);  // the row with its own dof stays
  const Eigen::VectorXd lambda = (Eigen::VectorXd(5) << 1, 0, 0, 0, 2).finished();
  const Eigen::VectorXd least = b.minimum_norm(lambda);
  EXPECT_LT((C.transpose() * (least - lambda)).norm(), 1e-14);  // the same forces
  EXPECT_LT((b.null_space.transpose() * least).norm(), 1e-12);  // nothing in ker Cᵀ
  EXPECT_LT(least.norm(), lambda.norm());
}

TEST(ConstraintBasis, RoundOffTermsDoNotMakeARowIndependent) {
  SparseMatrix C = rows_on_three_dofs();
  C.coeffRef(0, 3) = 7e-18;  // a tangent's round-off component on a free slave dof
  C.coeffRef(1, 3) = 5e-19;
  EXPECT_EQ(independent_rows(C).kept.size(), 4u);
}

}  // namespace test_constraint_basis
