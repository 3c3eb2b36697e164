#pragma once
// Exact comparisons of compressed sparse matrices: what decides that a cached factor, ordering or preconditioner
// still belongs to the matrix at hand (keyed to the rows themselves, not to their count).
#include <vector>

#include "solve/Factorization.h"

namespace rollsim {

/// Same shape and the same stored positions (compressed column storage compared index by index).
bool same_pattern(const SparseMatrix& a, const SparseMatrix& b);
/// Same pattern and bit-identical values.
bool same_matrix(const SparseMatrix& a, const SparseMatrix& b);

/// The positions of a compressed matrix without its values: what a symbolic analysis depends on, kept at a third of
/// the matrix's memory.
class SparsityPattern {
 public:
  SparsityPattern() = default;
  explicit SparsityPattern(const SparseMatrix& A);
  /// True when A has exactly these positions.
  bool matches(const SparseMatrix& A) const;

 private:
  Eigen::Index rows_ = -1, cols_ = -1;
  std::vector<int> outer_, inner_;
};

}  // namespace rollsim
