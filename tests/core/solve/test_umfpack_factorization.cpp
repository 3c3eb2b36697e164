// UmfpackFactorization's iterative refinement: UMFPACK's default takes steps on an indefinite matrix, and
// set_refinement_steps(0) (CholeskyOrLU's LU) takes none and still solves to near working precision.
#include <gtest/gtest.h>

#include "grid_matrix.h"
#include "solve/UmfpackFactorization.h"
#include "solve_error.h"

namespace test_umfpack_factorization {

using namespace rollsim;

namespace {
/// An FE-like 3D matrix shifted down by half its mean diagonal: symmetric indefinite, regular.
SparseMatrix indefinite_matrix() {
  SparseMatrix A = rollsim::testing::fe_grid_matrix(5, 3, 3, 7);
  const double shift = 0.5 * A.diagonal().mean();
  for (int i = 0; i < A.rows(); ++i) A.coeffRef(i, i) -= shift;
  return A;
}
}  // namespace

TEST(UmfpackFactorization, RefinementStepsCanBeTurnedOff) {
  const SparseMatrix A = indefinite_matrix();
  UmfpackFactorization refined, plain;
  plain.set_refinement_steps(0);
  for (UmfpackFactorization* f : {&refined, &plain}) f->analyze(A), f->factorize(A);
  EXPECT_LT(rollsim::testing::relative_solve_error(refined, A), 1e-10);
  EXPECT_LT(rollsim::testing::relative_solve_error(plain, A), 1e-10);
  EXPECT_GT(refined.refinement_steps(), 0) << "UMFPACK's default refines";
  EXPECT_EQ(plain.refinement_steps(), 0);
}

}  // namespace test_umfpack_factorization
