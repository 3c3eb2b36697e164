#include "solve/SupernodalSolve.h"

#include <algorithm>
#include <vector>

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

Eigen::MatrixXd supernodal_inverse_quadratic(const cholmod_factor& L, const Eigen::MatrixXd& E) {
  const auto n = static_cast<Eigen::Index>(L.n), k = E.cols();
  const int* perm = static_cast<const int*>(L.Perm);
  const int* super = static_cast<const int*>(L.super);
  std::vector<int> owner(static_cast<size_t>(n));  // the supernode of each (permuted) row
  for (size_t s = 0; s < L.nsuper; ++s)
    for (int i = super[s]; i < super[s + 1]; ++i) owner[static_cast<size_t>(i)] = static_cast<int>(s);
  Eigen::MatrixXd W(n, k);                         // P E, then L⁻¹ P E supernode by supernode
  std::vector<std::vector<int>> active(L.nsuper);  // columns whose reach includes the supernode
  for (Eigen::Index i = 0; i < n; ++i) {
    W.row(i) = E.row(perm ? perm[i] : i);
    for (Eigen::Index j = 0; j < k; ++j)
      if (W(i, j) != 0) active[static_cast<size_t>(owner[static_cast<size_t>(i)])].push_back(static_cast<int>(j));
  }
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(k, k);
  Eigen::MatrixXd X, T;
  for (size_t s = 0; s < L.nsuper; ++s) {
    std::vector<int>& a = active[s];
    if (a.empty()) continue;
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    const Supernode sn(L, s);
    const auto m = static_cast<Eigen::Index>(a.size());
    X.resize(sn.cols, m);
    for (Eigen::Index j = 0; j < m; ++j) X.col(j) = W.col(a[static_cast<size_t>(j)]).segment(sn.first, sn.cols);
    sn.block.topRows(sn.cols).triangularView<Eigen::Lower>().solveInPlace(X);  // W's rows of s are final now
    const Eigen::MatrixXd XtX = X.transpose() * X;
    for (Eigen::Index j = 0; j < m; ++j)
      for (Eigen::Index i = 0; i < m; ++i) out(a[static_cast<size_t>(i)], a[static_cast<size_t>(j)]) += XtX(i, j);
    if (sn.below() == 0) continue;
    T.noalias() = sn.block.bottomRows(sn.below()) * X;
    for (Eigen::Index j = 0; j < m; ++j) {
      auto w = W.col(a[static_cast<size_t>(j)]);
      for (int i = 0; i < sn.below(); ++i) w[sn.rows[sn.cols + i]] -= T(i, j);
    }
    std::vector<int>& up = active[static_cast<size_t>(owner[static_cast<size_t>(sn.rows[sn.cols])])];  // the parent
    up.insert(up.end(), a.begin(), a.end());
    std::vector<int>().swap(a);
  }
  return out;
}

}  // namespace rollsim
