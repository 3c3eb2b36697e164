#pragma once
// Skyline (profile) active-column LDL^T, the paper's "ACTCOL" baseline, on a reverse Cuthill-McKee ordering.
#include <vector>

#include "solve/Factorization.h"

namespace rollsim {

/// Crout active-column LDL^T without pivoting (SPD, or symmetric with non-singular leading minors such as a
/// saddle-point matrix with its multipliers last). Storage: the upper triangle of P A P^T column by column, each
/// column contiguous from its first non-zero row down to the diagonal; diag_[j] is the position of entry (j, j).
/// The reduction is ACTCOL's (same dot products, same operation count); only the columns are reduced in groups of
/// kBlock so that each loaded finished column serves several of them.
class SkylineFactorization final : public Factorization {
 public:
  /// The last `trailing` rows/cols of A (e.g. Lagrange multipliers) are kept last, in order, by the ordering.
  explicit SkylineFactorization(int trailing = 0) : trailing_(trailing) {}

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override;
  const FactorStats& stats() const override { return stats_; }

  /// Floating-point operations counted while running the last factorization (equals stats().flops).
  double counted_flops() const { return counted_flops_; }
  /// perm[k] = original index of the row/col at position k.
  const std::vector<int>& permutation() const { return perm_; }
  int size() const { return n_; }

 private:
  static constexpr int kBlock = 8;  // columns reduced together: they share the loads of the finished columns

  double* entry(int i, int j) { return a_.data() + (diag_[j] - (j - i)); }  // (i, j), first_[j] <= i <= j
  void scatter(const SparseMatrix& A);
  int eliminate();  // returns the (permuted) column of a failed pivot, or -1
  long reduce_block_rows(int j0, int nb);
  long finish_column(int j0, int j);
  long predicted_flops() const;

  int trailing_;
  double column_scale_ = 0;  // Σ of the magnitudes that formed the last finished pivot (its cancellation scale)
  int n_ = 0;
  bool analyzed_ = false, factored_ = false;
  std::vector<int> perm_, inverse_, first_;  // first_[j]: first stored row of column j
  std::vector<long> diag_;                   // ACTCOL's JDIAG: position of the diagonal of each column
  std::vector<double> a_;                    // the skyline; overwritten by U = L^T (unit) and D on the diagonal
  std::vector<double> original_diag_;        // A_jj before the reduction, for the pivot test
  double counted_flops_ = 0;
  FactorStats stats_;
};

}  // namespace rollsim
