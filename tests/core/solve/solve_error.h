#pragma once
// The relative error of a factorization's solve of A x = A x̂ for a known x̂ (1 … 2): the factorization tests' check.
#include <Eigen/Dense>

#include "solve/Factorization.h"

namespace rollsim::testing {

inline double relative_solve_error(Factorization& f, const SparseMatrix& A) {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(A.rows(), 1, 2);
  return (f.solve(A * x) - x).norm() / x.norm();
}

}  // namespace rollsim::testing
