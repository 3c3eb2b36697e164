#pragma once
// A group's factorization that accepts a symmetric indefinite matrix: CHOLMOD's supernodal LLᵀ while the matrix is
// positive definite, UMFPACK's LU with partial pivoting from the first factorization that meets a negative pivot on.
// A finite-strain subdomain under heavy compression needs it: alone (free on its interface faces, geometric
// stiffness included) its tangent turns indefinite while the whole body's is still positive definite (paper
// Example 5, docs/BENCHMARKS-NONLINEAR.md). A tiny positive pivot stays an error (a singular matrix, not an
// indefinite one), and so does an LU whose pivots span more than 1/kMinPivotRatio.
#include <memory>

#include "solve/CholmodFactorization.h"
#include "solve/UmfpackFactorization.h"

namespace rollsim {

class CholeskyOrLU final : public Factorization {
 public:
  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override;
  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd& B) override;
  Eigen::MatrixXd inverse_quadratic(const Eigen::MatrixXd& E) override;
  const FactorStats& stats() const override { return stats_; }
  /// True once a factorization met a negative pivot: the LU holds the factor (and keeps it for the later values).
  bool indefinite() const { return lu_ != nullptr; }

 private:
  void factorize_lu(const SparseMatrix& A);
  void sum_stats();
  CholmodFactorization cholesky_;
  std::unique_ptr<UmfpackFactorization> lu_;
  FactorStats stats_;
};

}  // namespace rollsim
