#pragma once
// CHOLMOD supernodal Cholesky with CHOLMOD's choice of AMD / METIS ordering (the modern baseline). Solves go
// through supernodal_solve (SupernodalSolve.h), not cholmod_solve. One object is used by one thread at a time.
#include <cholmod.h>

#include "solve/Factorization.h"

namespace rollsim {

class CholmodFactorization final : public Factorization {
 public:
  CholmodFactorization();
  ~CholmodFactorization() override;
  CholmodFactorization(const CholmodFactorization&) = delete;
  CholmodFactorization& operator=(const CholmodFactorization&) = delete;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override;
  const FactorStats& stats() const override { return stats_; }

 private:
  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  Eigen::VectorXd work_;  // supernodal_solve's scratch
  FactorStats stats_;
};

}  // namespace rollsim
