#include "solve/SupernodalSolve.h"

namespace rollsim {

namespace {
using Block = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;

/// Supernode s of L: the dense column block (its rows: the diagonal block first, then the rows below it).
struct Supernode {
  Supernode(const cholmod_factor& L, size_t s)
      : first(static_cast<const int*>(L.super)[s]),
        cols(static_cast<const int*>(L.super)[s + 1] - first),
        rows(static_cast<const int*>(L.s) + static_cast<const int*>(L.pi)[s]),
        nrows(static_cast<const int*>(L.pi)[s + 1] - static_cast<const int*>(L.pi)[s]),
        block(static_cast<const double*>(L.x) + static_cast<const int*>(L.px)[s], nrows, cols,
              Eigen::OuterStride<>(nrows)) {}
  int below() const { return nrows - cols; }
  int first, cols;
  const int* rows;  // global row indices, `nrows` of them
  int nrows;
  Block block;
};
}  // namespace

Eigen::VectorXd supernodal_solve(const cholmod_factor& L, const Eigen::VectorXd& b, Eigen::VectorXd& work) {
  const auto n = static_cast<Eigen::Index>(L.n);
  const int* perm = static_cast<const int*>(L.Perm);
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i) y[i] = b[perm ? perm[i] : i];
  if (work.size() < static_cast<Eigen::Index>(L.maxesize)) work.resize(static_cast<Eigen::Index>(L.maxesize));
  for (size_t s = 0; s < L.nsuper; ++s) {  // L y = P b, column blocks left to right
    const Supernode sn(L, s);
    auto x1 = y.segment(sn.first, sn.cols);
    sn.block.topRows(sn.cols).triangularView<Eigen::Lower>().solveInPlace(x1);
    if (sn.below() == 0) continue;
    auto t = work.head(sn.below());
    t.noalias() = sn.block.bottomRows(sn.below()) * x1;
    for (int i = 0; i < sn.below(); ++i) y[sn.rows[sn.cols + i]] -= t[i];
  }
  for (size_t s = L.nsuper; s-- > 0;) {  // Lᵀ z = y, right to left
    const Supernode sn(L, s);
    auto x1 = y.segment(sn.first, sn.cols);
    if (sn.below() > 0) {
      auto t = work.head(sn.below());
      for (int i = 0; i < sn.below(); ++i) t[i] = y[sn.rows[sn.cols + i]];
      x1.noalias() -= sn.block.bottomRows(sn.below()).transpose() * t;
    }
    sn.block.topRows(sn.cols).triangularView<Eigen::Lower>().transpose().solveInPlace(x1);
  }
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) x[perm ? perm[i] : i] = y[i];
  return x;
}

}  // namespace rollsim
