#include "solve/CholeskyOrLU.h"

#include <cstdio>

namespace rollsim {

void CholeskyOrLU::analyze(const SparseMatrix& A) {
  if (lu_)
    lu_->analyze(A);
  else
    cholesky_.analyze(A);
  sum_stats();
}

void CholeskyOrLU::factorize(const SparseMatrix& A) {
  if (!lu_) {
    try {
      cholesky_.factorize(A);
      sum_stats();
      return;
    } catch (const NotPositiveDefinite&) {  // indefinite (or singular): LU from now on
      lu_ = std::make_unique<UmfpackFactorization>();
      // no iterative refinement: the group's solves run inside the interface Krylov method, and UMFPACK's default
      // steps (one in nearly every solve) cost 35 % of Example 5's CPU under feti 1x2x1 (BENCHMARKS-NONLINEAR)
      lu_->set_refinement_steps(0);
      lu_->analyze(A);
    }
  }
  factorize_lu(A);
}

void CholeskyOrLU::factorize_lu(const SparseMatrix& A) {
  try {
    lu_->factorize(A);
  } catch (const SingularMatrix&) {
    sum_stats();
    throw SingularMatrix("matrix is singular (an exact zero pivot in its LU factor)", -1);
  }
  sum_stats();
  if (!(lu_->rcond() > kMinPivotRatio)) {
    char what[120];
    std::snprintf(what, sizeof what, "pivot %.3g of the largest in the LU factor of an indefinite matrix",
                  lu_->rcond());
    throw SingularMatrix(what, -1);
  }
}

Eigen::VectorXd CholeskyOrLU::solve(const Eigen::VectorXd& b) {
  Eigen::VectorXd x = lu_ ? lu_->solve(b) : cholesky_.solve(b);
  stats_.solve_s = cholesky_.stats().solve_s + (lu_ ? lu_->stats().solve_s : 0.0);  // no full copy per solve
  return x;
}

Eigen::MatrixXd CholeskyOrLU::solve_columns(const Eigen::MatrixXd& B) {
  Eigen::MatrixXd X = lu_ ? lu_->solve_columns(B) : cholesky_.solve_columns(B);
  stats_.solve_s = cholesky_.stats().solve_s + (lu_ ? lu_->stats().solve_s : 0.0);
  return X;
}

Eigen::MatrixXd CholeskyOrLU::inverse_quadratic(const Eigen::MatrixXd& E) {
  Eigen::MatrixXd X = lu_ ? lu_->inverse_quadratic(E) : cholesky_.inverse_quadratic(E);
  stats_.solve_s = cholesky_.stats().solve_s + (lu_ ? lu_->stats().solve_s : 0.0);
  return X;
}

void CholeskyOrLU::sum_stats() {
  const FactorStats& c = cholesky_.stats();
  stats_ = c;
  if (!lu_) return;
  const FactorStats& l = lu_->stats();
  stats_.ordering = l.ordering;
  stats_.nnz_factor = l.nnz_factor;
  stats_.flops = l.flops;
  stats_.analyze_s += l.analyze_s, stats_.factorize_s += l.factorize_s, stats_.solve_s += l.solve_s;
  stats_.factorizations += l.factorizations;
  stats_.min_pivot_ratio = l.factorizations ? lu_->rcond() : c.min_pivot_ratio;
}

}  // namespace rollsim
