// Skyline active-column (Crout) LDL^T with reverse Cuthill-McKee ordering: analysis, factorization, solution.
#include "solve/SkylineFactorization.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "base/Stopwatch.h"
#include "solve/ReverseCuthillMcKee.h"

namespace rollsim {
namespace {

/// Dot product of two contiguous segments (Eigen's vectorised reduction).
inline double dot(const double* x, const double* y, int len) {
  return Eigen::Map<const Eigen::VectorXd>(x, len).dot(Eigen::Map<const Eigen::VectorXd>(y, len));
}

using Lanes = Eigen::Array4d;  // SIMD lanes of the fused kernel: two SSE2 packets or one AVX packet
constexpr int kW = 4;

/// s[b] = x . y[b] over len contiguous terms for B segments y[b]: each load of x serves all of them.
template <int B>
inline void dot_block(const double* x, const std::array<const double*, B>& y, int len, std::array<double, B>& s) {
  std::array<Lanes, B> acc;
  for (auto& a : acc) a.setZero();
  int k = 0;
  for (; k + kW <= len; k += kW) {
    const Lanes xk = Eigen::Map<const Lanes>(x + k);
    for (int b = 0; b < B; ++b) acc[b] += xk * Eigen::Map<const Lanes>(y[b] + k);
  }
  for (int b = 0; b < B; ++b) s[b] = acc[b].sum();
  for (; k < len; ++k)
    for (int b = 0; b < B; ++b) s[b] += x[k] * y[b][k];
}

std::string pivot_message(double d, double ajj, int col, int k, int n) {
  char what[200];
  if (d > 0 && ajj > 0)
    std::snprintf(what, sizeof what, "pivot %.3g of its diagonal in skyline LDL^T at column %d (pivot %d of %d)",
                  d / ajj, col, k, n);
  else
    std::snprintf(what, sizeof what, "non-positive pivot %.3g in skyline LDL^T at column %d (pivot %d of %d)", d, col,
                  k, n);
  return what;
}

}  // namespace

void SkylineFactorization::analyze(const SparseMatrix& A) {
  Stopwatch t;
  if (A.rows() != A.cols()) throw std::invalid_argument("SkylineFactorization: matrix is not square");
  n_ = static_cast<int>(A.rows());
  if (trailing_ < 0 || trailing_ > n_) throw std::invalid_argument("SkylineFactorization: bad trailing count");
  // The profile-minimising choice between RCM and the given numbering (the mesh numbers nodes along the
  // shortest direction, which beats RCM on cube-like 3D meshes where RCM's level sets are shells).
  perm_ = reverse_cuthill_mckee(A, trailing_);
  std::vector<int> given(static_cast<size_t>(n_));
  std::iota(given.begin(), given.end(), 0);
  const bool keep_given = profile_size(A, given) < profile_size(A, perm_);
  if (keep_given) perm_ = std::move(given);
  inverse_.assign(static_cast<size_t>(n_), 0);
  for (int k = 0; k < n_; ++k) inverse_[perm_[k]] = k;
  first_ = skyline_first_rows(A, perm_);
  diag_.resize(static_cast<size_t>(n_));
  long next = 0;
  for (int j = 0; j < n_; ++j) diag_[j] = (next += j - first_[j] + 1) - 1;
  check_factor_fits(static_cast<double>(next) * sizeof(double), n_, "the skyline profile");
  a_.assign(static_cast<size_t>(next), 0.0);
  stats_.ordering = keep_given ? "natural (mesh numbering, smaller profile than RCM)" : "RCM";
  stats_.nnz_factor = static_cast<double>(next);
  stats_.flops = static_cast<double>(predicted_flops());
  analyzed_ = true;
  factored_ = false;
  stats_.analyze_s += t.seconds();
}

/// Crout reduction of column j: for each row i of its active range a dot product over the overlap of columns i and
/// j (2 flops per term), then per off-diagonal entry one division and one multiply-subtract into d_j (3 flops).
long SkylineFactorization::predicted_flops() const {
  long flops = 0;
  for (int j = 0; j < n_; ++j)
    for (int i = first_[j]; i < j; ++i) flops += 2L * (i - std::max(first_[i], first_[j])) + 3;
  return flops;
}

void SkylineFactorization::scatter(const SparseMatrix& A) {
  std::fill(a_.begin(), a_.end(), 0.0);
  for (int c = 0; c < n_; ++c)
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
      if (it.row() > c) continue;  // the upper triangle of A is used, the lower one is ignored
      const int p = inverse_[it.row()], q = inverse_[c];
      const int i = std::min(p, q), j = std::max(p, q);
      if (i < first_[j]) throw std::invalid_argument("SkylineFactorization: pattern differs from the analyzed one");
      a_[diag_[j] - (j - i)] = it.value();
    }
  original_diag_.resize(static_cast<size_t>(n_));
  for (int j = 0; j < n_; ++j) original_diag_[j] = a_[diag_[j]];
}

/// Rows i < j0 of the block of columns j0 .. j0 + nb - 1 (all columns i already factored): u_ij -= l_i . u_j over
/// the overlap of the two columns. Where all kBlock columns are active the dot products share the loads of column i.
long SkylineFactorization::reduce_block_rows(int j0, int nb) {
  long flops = 0;
  const int lo = *std::min_element(first_.begin() + j0, first_.begin() + j0 + nb);
  for (int i = lo; i < j0; ++i) {
    int shared = first_[i], active = 0;
    for (int j = j0; j < j0 + nb; ++j) {
      if (first_[j] > i) continue;
      shared = std::max(shared, first_[j]);
      ++active;
    }
    if (active < kBlock) shared = i;      // no fused part: each active column does its own dot product below
    for (int j = j0; j < j0 + nb; ++j) {  // the parts of the overlaps before `shared`
      const int k0 = std::max(first_[i], first_[j]);
      if (first_[j] > i || k0 >= shared) continue;
      *entry(i, j) -= dot(entry(k0, i), entry(k0, j), shared - k0);
      flops += 2L * (shared - k0);
    }
    if (active < kBlock) continue;
    std::array<const double*, kBlock> y;
    for (int b = 0; b < kBlock; ++b) y[b] = entry(shared, j0 + b);
    std::array<double, kBlock> s{};
    dot_block<kBlock>(entry(shared, i), y, i - shared, s);
    for (int b = 0; b < kBlock; ++b) *entry(i, j0 + b) -= s[b];
    flops += 2L * kBlock * (i - shared);
  }
  return flops;
}

/// Completes column j of the block starting at j0: rows j0 .. j-1, then U(:, j) -> L(j, :)^T and d_j in place.
long SkylineFactorization::finish_column(int j0, int j) {
  const int fj = first_[j];
  long flops = 0;
  for (int i = std::max(j0, fj); i < j; ++i) {
    const int k0 = std::max(first_[i], fj);
    *entry(i, j) -= dot(entry(k0, i), entry(k0, j), i - k0);
    flops += 2L * (i - k0);
  }
  double* col = entry(fj, j);  // col[i - fj] = entry (i, j)
  double dj = col[j - fj];
  column_scale_ = std::abs(dj);
  for (int i = fj; i < j; ++i) {
    const double u = col[i - fj];
    col[i - fj] = u / a_[diag_[i]];
    dj -= u * col[i - fj];
    column_scale_ += std::abs(u * col[i - fj]);
  }
  col[j - fj] = dj;
  return flops + 3L * (j - fj);
}

int SkylineFactorization::eliminate() {
  long flops = 0;
  int failed = -1;
  for (int j0 = 0; j0 < n_ && failed < 0; j0 += kBlock) {
    const int nb = std::min(kBlock, n_ - j0);
    flops += reduce_block_rows(j0, nb);
    for (int j = j0; j < j0 + nb; ++j) {
      flops += finish_column(j0, j);
      const double d = a_[diag_[j]];
      bool bad = !std::isfinite(d);
      if (j < n_ - trailing_) {  // the stiffness part: positive definite, pivots checked against their diagonal
        const double ratio = original_diag_[j] > 0 ? d / original_diag_[j] : 0.0;
        stats_.min_pivot_ratio = std::min(stats_.min_pivot_ratio, ratio);
        bad = bad || !(ratio > kMinPivotRatio);
      } else {  // multiplier rows: d_j = −c K⁻¹ cᵀ of its own scale (1/K), singular when it cancels to round-off
        bad = bad || std::abs(d) <= kMinPivotRatio * column_scale_;
      }
      if (bad) {
        failed = j;
        break;
      }
    }
  }
  counted_flops_ = static_cast<double>(flops);
  return failed;
}

void SkylineFactorization::factorize(const SparseMatrix& A) {
  if (!analyzed_ || A.rows() != n_ || A.cols() != n_) analyze(A);
  Stopwatch t;
  factored_ = false;
  scatter(A);
  stats_.min_pivot_ratio = 1;
  const int failed = eliminate();
  stats_.factorize_s += t.seconds();
  ++stats_.factorizations;
  if (failed >= 0)
    throw SingularMatrix(pivot_message(a_[diag_[failed]], original_diag_[failed], perm_[failed], failed, n_),
                         perm_[failed]);
  factored_ = true;
}

Eigen::VectorXd SkylineFactorization::solve(const Eigen::VectorXd& b) {
  if (!factored_) throw std::logic_error("SkylineFactorization::solve called without a successful factorize");
  if (b.size() != n_) throw std::invalid_argument("SkylineFactorization::solve: right-hand side has the wrong size");
  Stopwatch t;
  Eigen::VectorXd y(n_);
  for (int k = 0; k < n_; ++k) y[k] = b[perm_[k]];
  for (int j = 0; j < n_; ++j) {  // L y = P b: row j of L is column j of U
    const int len = j - first_[j];
    y[j] -= dot(a_.data() + (diag_[j] - len), y.data() + first_[j], len);
  }
  for (int j = 0; j < n_; ++j) y[j] /= a_[diag_[j]];
  for (int j = n_ - 1; j > 0; --j) {  // U x = y, column by column
    const int len = j - first_[j];
    Eigen::Map<Eigen::VectorXd>(y.data() + first_[j], len) -=
        y[j] * Eigen::Map<const Eigen::VectorXd>(a_.data() + (diag_[j] - len), len);
  }
  Eigen::VectorXd x(n_);
  for (int k = 0; k < n_; ++k) x[perm_[k]] = y[k];
  stats_.solve_s += t.seconds();
  return x;
}

}  // namespace rollsim
