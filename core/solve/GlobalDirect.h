#pragma once
// Strategies "skyline" and "direct": one global matrix (groups stacked on the diagonal;
// constraint rows last once contact exists) factored by a single sparse factorization — again only when a group's
// version (the update policy) or the constraint rows changed. Linearly dependent constraint rows are left out of the
// matrix (solve/ConstraintBasis) and their multipliers recovered as the least-norm λ with the same forces.
#include "solve/BorderedMatrix.h"
#include "solve/ConstraintBasis.h"
#include "solve/SolverStrategy.h"
#include "solve/SparseCompare.h"

namespace rollsim {

class GlobalDirect final : public SolverStrategy {
 public:
  explicit GlobalDirect(std::string factorization_kind);
  BlockSolution solve(const BlockSystem& system, AnalysisObserver* observer = nullptr) override;
  const SolveStats& stats() const override { return stats_; }
  /// UMFPACK's LU factors the bordered matrix whatever its symmetry (skyline's LDLᵀ needs it symmetric).
  bool solves_unsymmetric() const override { return kind_ == "cholmod"; }
  bool assembles_globally() const override { return true; }

 private:
  std::string kind_;
  std::unique_ptr<Factorization> factor_;
  SparseMatrix global_;
  ConstraintBasis basis_;  // the independent constraint rows of the factored matrix (all of them, as a rule)
  void add_times(const FactorStats& s);
  /// (Re-)analyses when the pattern changed, factors A, records the versions and blocks it holds.
  void factorize(const BlockSystem& sys, const SparseMatrix& A, AnalysisObserver* observer);
  BorderedFactorKey key_;     // what the factor was made from
  SparsityPattern analyzed_;  // of the last analysis: a new pattern (not only a new size) needs a new one
  long trailing_ = 0;
  FactorStats earlier_;       // times of factors replaced by a new pattern (active-set changes)
  double earlier_flops_ = 0;  // and their flops
  SolveStats stats_;
};

}  // namespace rollsim
