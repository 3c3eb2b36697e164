#include "solve/ConstraintBasis.h"

#include <Eigen/Cholesky>
#include <Eigen/SparseQR>
#include <algorithm>

namespace rollsim {

Eigen::VectorXd ConstraintBasis::minimum_norm(const Eigen::VectorXd& lambda) const {
  if (full_rank()) return lambda;
  const Eigen::MatrixXd& N = null_space;
  return lambda - N * (N.transpose() * N).ldlt().solve(N.transpose() * lambda);
}

ConstraintBasis independent_rows(const SparseMatrix& C) {
  ConstraintBasis out;
  const long m = C.rows();
  if (m == 0) return out;
  SparseMatrix Ct = C.transpose();
  Ct.makeCompressed();
  double largest = 0;
  for (int j = 0; j < Ct.outerSize(); ++j) largest = std::max(largest, Ct.col(j).norm());
  // Cᵀ P = Q [R11 R12; 0 0]: the first `rank` columns of P are independent rows of C, and the columns of
  // P [−R11⁻¹R12; I] span ker Cᵀ
  Eigen::SparseQR<SparseMatrix, Eigen::COLAMDOrdering<int>> qr;
  qr.setPivotThreshold(1e-10 * std::max(largest, 1e-300));
  qr.compute(Ct);
  const long r = qr.rank();
  const auto& perm = qr.colsPermutation().indices();
  for (long k = 0; k < r; ++k) out.kept.push_back(perm[k]);
  std::sort(out.kept.begin(), out.kept.end());
  if (r == m) return out;
  const Eigen::MatrixXd R = Eigen::MatrixXd(qr.matrixR()).topRows(r);
  const Eigen::MatrixXd coef = R.leftCols(r).triangularView<Eigen::Upper>().solve(R.rightCols(m - r));  // R11⁻¹R12
  out.null_space = Eigen::MatrixXd::Zero(m, m - r);
  for (long j = 0; j < m - r; ++j) {
    for (long k = 0; k < r; ++k) out.null_space(perm[k], j) = -coef(k, j);
    out.null_space(perm[r + j], j) = 1.0;
  }
  return out;
}

SparseMatrix stacked_constraints(const BlockSystem& sys) {
  std::vector<Eigen::Triplet<double, int>> t;
  long offset = 0;
  for (const Group& g : sys.groups) {
    for (int j = 0; j < g.C.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(g.C, j); it; ++it)
        t.emplace_back(it.row(), static_cast<int>(offset + j), it.value());
    offset += g.C.cols();
  }
  SparseMatrix C(static_cast<int>(sys.num_multipliers()), static_cast<int>(offset));
  C.setFromTriplets(t.begin(), t.end());
  return C;
}

}  // namespace rollsim
