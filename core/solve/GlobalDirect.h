#pragma once
// Strategies "skyline" and "direct": one global matrix (groups stacked on the diagonal;
// constraint rows last once contact exists) factored by a single sparse factorization.
#include "solve/SolverStrategy.h"

namespace rollsim {

class GlobalDirect final : public SolverStrategy {
 public:
  explicit GlobalDirect(std::string factorization_kind);
  std::vector<Eigen::VectorXd> solve(const BlockSystem& system) override;
  const SolveStats& stats() const override { return stats_; }

 private:
  std::string kind_;
  std::unique_ptr<Factorization> factor_;
  SparseMatrix global_;
  SolveStats stats_;
};

}  // namespace rollsim
