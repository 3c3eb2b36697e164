#include "solve/BorderedMatrix.h"

#include <cstdio>

#include "solve/Factorization.h"
#include "solve/SparseCompare.h"

namespace rollsim {

namespace {

void add_block(Triplets& t, const SparseMatrix& A, long row0, long col0, bool transpose) {
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      const long r = row0 + (transpose ? j : it.row()), c = col0 + (transpose ? it.row() : j);
      t.emplace_back(static_cast<int>(r), static_cast<int>(c), it.value());
    }
}

/// The rows `kept` of C, in their order.
SparseMatrix select_rows(const SparseMatrix& C, const std::vector<int>& kept) {
  SparseMatrix S(static_cast<int>(kept.size()), static_cast<int>(C.rows()));
  Triplets t;
  for (size_t i = 0; i < kept.size(); ++i) t.emplace_back(static_cast<int>(i), kept[i], 1.0);
  S.setFromTriplets(t.begin(), t.end());
  return S * C;
}

}  // namespace

Triplets bordered_entries(const BlockSystem& sys, const std::vector<int>& kept, const std::vector<char>& stiffness,
                          bool border) {
  const long n = sys.num_dofs();
  Triplets t;
  long offset = 0;
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    const Group& group = sys.groups[g];
    if (stiffness.empty() || stiffness[g]) add_block(t, group.K, offset, offset, false);
    if (border && !kept.empty()) {
      add_block(t, select_rows(group.C, kept), n, offset, false);
      add_block(t, select_rows(group.equation_C(), kept), offset, n, true);
    }
    offset += group.C.cols();
  }
  if (border && sys.coupling.nonZeros() > 0) add_block(t, sys.coupling, 0, 0, false);  // stiffness joining groups
  return t;
}

SparseMatrix bordered_matrix(const BlockSystem& sys, const std::vector<int>& kept) {
  const long size = sys.num_dofs() + static_cast<long>(kept.size());
  const Triplets t = bordered_entries(sys, kept, {}, true);
  SparseMatrix A(size, size);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

bool BorderedFactorKey::matches(const BlockSystem& sys) const {
  if (versions_.empty() || versions_.size() != sys.groups.size() || !same_matrix(coupling_, sys.coupling)) return false;
  for (size_t g = 0; g < sys.groups.size(); ++g)
    if (versions_[g] != sys.groups[g].version || !same_matrix(C_[g], sys.groups[g].C) ||
        !same_matrix(C_eq_[g], sys.groups[g].C_eq))
      return false;
  return true;
}

void BorderedFactorKey::record(const BlockSystem& sys) {
  versions_.clear();
  C_.clear();
  C_eq_.clear();
  coupling_ = sys.coupling;
  for (const Group& g : sys.groups) {
    versions_.push_back(g.version);
    C_.push_back(g.C);
    C_eq_.push_back(g.C_eq);
  }
}

void check_backward_error(double error) {
  if (error <= 1e-8) return;
  char what[160];
  std::snprintf(what, sizeof what,
                "the direct solve's backward error is %.3g (round-off is ~1e-16): the matrix is singular to working "
                "precision",
                error);
  throw SingularMatrix(what, -1);
}

}  // namespace rollsim
