#include "solve/SparseCompare.h"

#include <algorithm>

namespace rollsim {

namespace {
/// `a` itself when compressed, else a compressed copy held in `copy`.
const SparseMatrix& compressed(const SparseMatrix& a, SparseMatrix& copy) {
  if (a.isCompressed()) return a;
  copy = a;
  copy.makeCompressed();
  return copy;
}
}  // namespace

bool same_pattern(const SparseMatrix& a_in, const SparseMatrix& b_in) {
  if (a_in.rows() != b_in.rows() || a_in.cols() != b_in.cols() || a_in.nonZeros() != b_in.nonZeros()) return false;
  SparseMatrix ca, cb;
  const SparseMatrix &a = compressed(a_in, ca), &b = compressed(b_in, cb);
  const auto nnz = static_cast<size_t>(a.nonZeros());
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + nnz, b.innerIndexPtr());
}

bool same_matrix(const SparseMatrix& a_in, const SparseMatrix& b_in) {
  if (!same_pattern(a_in, b_in)) return false;
  SparseMatrix ca, cb;
  const SparseMatrix &a = compressed(a_in, ca), &b = compressed(b_in, cb);
  return std::equal(a.valuePtr(), a.valuePtr() + a.nonZeros(), b.valuePtr());
}

SparsityPattern::SparsityPattern(const SparseMatrix& A_in) : rows_(A_in.rows()), cols_(A_in.cols()) {
  SparseMatrix copy;
  const SparseMatrix& A = compressed(A_in, copy);
  outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
  inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
}

bool SparsityPattern::matches(const SparseMatrix& A_in) const {
  if (A_in.rows() != rows_ || A_in.cols() != cols_ || A_in.nonZeros() != static_cast<Eigen::Index>(inner_.size()))
    return false;
  SparseMatrix copy;
  const SparseMatrix& A = compressed(A_in, copy);
  return std::equal(outer_.begin(), outer_.end(), A.outerIndexPtr()) &&
         std::equal(inner_.begin(), inner_.end(), A.innerIndexPtr());
}

}  // namespace rollsim
