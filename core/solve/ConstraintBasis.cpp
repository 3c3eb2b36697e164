#include "solve/ConstraintBasis.h"

#include <Eigen/Cholesky>
#include <Eigen/SparseQR>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "solve/Factorization.h"

namespace rollsim {

Eigen::VectorXd ConstraintBasis::minimum_norm(const Eigen::VectorXd& lambda) const {
  if (full_rank()) return lambda;
  const Eigen::MatrixXd& N = null_space;
  return lambda - N * (N.transpose() * N).ldlt().solve(N.transpose() * lambda);
}

Eigen::VectorXd ConstraintBasis::every_row(const Eigen::VectorXd& kept_lambda, long rows) const {
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(rows);  // a dependent row's share of the force goes to the rows it
  for (size_t i = 0; i < kept.size(); ++i) lambda[kept[i]] = kept_lambda[static_cast<long>(i)];  // depends on…
  return minimum_norm(lambda);  // …then spread as the interface CG spreads it
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

/// How far a dependent row may miss, relative to the largest d or u or to the terms d was computed from
/// (BlockSystem::d_reference). Not round-off alone: four stick rows on three roll dofs (the 3D pass's symmetry plane)
/// ask the roll for four anchors' axial positions, which agree only as well as the iterate that set them — on the
/// pass 48 × 24 × 8, 3.4e-11 mm, where a slack relative to the Newton correction alone (8e-13 mm late in a step)
/// cut `direct`'s steps back eight times at 20 % of its first millimetre while `mixed` ran on. Contradicting
/// constraints (two rows asking different things of the same dofs) miss by the order of d itself.
namespace {
constexpr double kDependentRowSlack = 1e-6;
}  // namespace

/// The rows left out as dependent hold too: C_j u = d_j to round-off of its terms. Otherwise they contradict the rows
/// they depend on (two constraints asking different things of the same dofs) and no solution exists.
void check_dependent_rows(const BlockSystem& sys, const ConstraintBasis& basis, const std::vector<Eigen::VectorXd>& u) {
  Eigen::VectorXd Cu = Eigen::VectorXd::Zero(sys.num_multipliers());
  double scale = std::max(sys.d.size() ? sys.d.lpNorm<Eigen::Infinity>() : 0.0, sys.d_reference);
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    Cu += sys.groups[g].C * u[g];
    scale = std::max(scale, u[g].size() ? u[g].lpNorm<Eigen::Infinity>() : 0.0);
  }
  std::vector<char> kept(static_cast<size_t>(sys.num_multipliers()), 0);
  for (int r : basis.kept) kept[static_cast<size_t>(r)] = 1;
  for (long r = 0; r < sys.num_multipliers(); ++r)
    if (const double miss = std::abs(Cu[r] - sys.d[r]);
        !kept[static_cast<size_t>(r)] && !(miss <= kDependentRowSlack * std::max(scale, 1e-300))) {
      char what[200];
      std::snprintf(what, sizeof what,
                    "constraint row %ld depends on other rows and contradicts them by %.3g (its tolerance %.3g; the "
                    "constraints have no solution)",
                    r, miss, kDependentRowSlack * scale);
      throw SingularMatrix(what, -1);
    }
}

}  // namespace rollsim
