#pragma once
// UMFPACK sparse LU with partial pivoting: the `direct` factorization of the saddle-point matrix (1), which is
// symmetric but indefinite and whose stiffness blocks may be singular (floating bodies) — Cholesky cannot, and an
// LDLᵀ without pivoting may meet a zero pivot there. See docs/ARCHITECTURE.md for the measured choice.
#include "solve/Factorization.h"

namespace rollsim {

class UmfpackFactorization final : public Factorization {
 public:
  UmfpackFactorization();
  ~UmfpackFactorization() override;
  UmfpackFactorization(const UmfpackFactorization&) = delete;
  UmfpackFactorization& operator=(const UmfpackFactorization&) = delete;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override;
  const FactorStats& stats() const override { return stats_; }
  /// UMFPACK's estimate of the reciprocal condition number, min |U_jj| / max |U_jj| of the last factorization
  double rcond() const { return rcond_; }
  /// At most `steps` steps of iterative refinement per solve (UMFPACK's default: 2). Each step costs about a solve
  /// and a product with A; a solve inside a Krylov method (a group's K⁺ under `mixed`/`feti`) can do without.
  void set_refinement_steps(int steps);
  /// Refinement steps taken over all solves so far.
  long refinement_steps() const { return refinement_steps_; }

 private:
  void free_numeric();
  SparseMatrix A_;  // UMFPACK keeps pointers into the matrix it factored
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  double control_[20]{};
  FactorStats stats_;
  double rcond_ = 0;
  double factor_bytes_ = 0;  // the symbolic analysis's estimate of the numeric factors [bytes]
  long refinement_steps_ = 0;
};

}  // namespace rollsim
