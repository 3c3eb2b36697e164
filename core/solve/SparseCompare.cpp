#include "solve/SparseCompare.h"

#include <algorithm>

namespace rollsim {

bool same_pattern(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  if (!a.isCompressed() || !b.isCompressed()) return same_pattern(SparseMatrix(a), SparseMatrix(b));
  const auto nnz = static_cast<size_t>(a.nonZeros());
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + nnz, b.innerIndexPtr());
}

bool same_matrix(const SparseMatrix& a, const SparseMatrix& b) {
  if (!same_pattern(a, b)) return false;
  if (!a.isCompressed() || !b.isCompressed()) return same_matrix(SparseMatrix(a), SparseMatrix(b));
  return std::equal(a.valuePtr(), a.valuePtr() + a.nonZeros(), b.valuePtr());
}

}  // namespace rollsim
