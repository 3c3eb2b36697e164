#include "solve/GlobalDirect.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "solve/BorderedMatrix.h"
#include "solve/SparseCompare.h"

namespace rollsim {

namespace {
/// The normwise backward error of the solve, refused above round-off (solve/BorderedMatrix).
void check_solution(const SparseMatrix& A, const Eigen::VectorXd& x, const Eigen::VectorXd& f) {
  if (!x.allFinite()) return;  // overflow: the caller's check of the results names the magnitudes
  double norm_A = 0;
  for (int j = 0; j < A.outerSize(); ++j) {  // the largest column sum: ‖A‖∞ (‖A‖₁ when A is unsymmetric)
    double sum = 0;
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) sum += std::abs(it.value());
    norm_A = std::max(norm_A, sum);
  }
  const double scale = norm_A * x.lpNorm<Eigen::Infinity>() + f.lpNorm<Eigen::Infinity>();
  if (std::isfinite(scale)) check_backward_error((A * x - f).lpNorm<Eigen::Infinity>() / std::max(scale, 1e-300));
}
}  // namespace

GlobalDirect::GlobalDirect(std::string kind) : kind_(std::move(kind)) {}

void GlobalDirect::add_times(const FactorStats& s) {
  earlier_.analyze_s += s.analyze_s;
  earlier_.factorize_s += s.factorize_s;
  earlier_.solve_s += s.solve_s;
  earlier_flops_ += s.flops_total();
}

void GlobalDirect::factorize(const BlockSystem& sys, const SparseMatrix& A, AnalysisObserver* observer) {
  const long m = static_cast<long>(basis_.kept.size());
  if (!factor_ || trailing_ != m || !analyzed_.matches(A)) {  // an active-set swap changes the pattern
    if (factor_) add_times(factor_->stats());                 // a new pattern: keep what the old spent
    factor_ = make_factorization(kind_, static_cast<int>(m));
    analyzed_ = SparsityPattern(A);
    trailing_ = m;
    factor_->analyze(A);
  }
  factor_->factorize(A);
  key_.record(sys);
  for (const Group& g : sys.groups) {
    ++stats_.factorizations[g.name];
    if (observer) observer->on_factorization(g.name);
  }
}

BlockSolution GlobalDirect::solve(const BlockSystem& sys, AnalysisObserver* observer) {
  const long n = sys.num_dofs(), m = sys.num_multipliers();
  if (kind_ == "skyline" && sys.num_rigid_modes() > 0)
    throw std::invalid_argument("solver 'skyline' eliminates without pivoting and cannot factor a floating body (" +
                                std::to_string(sys.num_rigid_modes()) +
                                " rigid modes held only by contact): use 'direct' or 'mixed'");
  const bool single = sys.groups.size() == 1 && m == 0;
  const bool refactor =
      !factor_ || !key_.matches(sys);  // the update policy's versions, or constraint rows that changed
  if (refactor) {
    basis_ = independent_rows(stacked_constraints(sys));
    if (!single) global_ = bordered_matrix(sys, basis_.kept);
  }
  const SparseMatrix& A = single ? sys.groups[0].K : global_;
  const long k = static_cast<long>(basis_.kept.size());
  Eigen::VectorXd f(n + k);
  long offset = 0;
  for (const Group& g : sys.groups) {
    f.segment(offset, g.f.size()) = g.f;
    offset += g.f.size();
  }
  for (long i = 0; i < k; ++i) f[n + i] = sys.d[basis_.kept[static_cast<size_t>(i)]];
  if (refactor) factorize(sys, A, observer);
  const Eigen::VectorXd x = factor_->solve(f);
  check_solution(A, x, f);
  const int solve = ++stats_.solves;
  stats_.factor = factor_->stats();
  stats_.analyze_s = earlier_.analyze_s + stats_.factor.analyze_s;
  stats_.factorize_s = earlier_.factorize_s + stats_.factor.factorize_s;
  stats_.solve_s = earlier_.solve_s + stats_.factor.solve_s;
  stats_.factor_flops_total = earlier_flops_ + stats_.factor.flops_total();
  BlockSolution out;
  offset = 0;
  for (const Group& g : sys.groups) {
    out.u.push_back(x.segment(offset, g.f.size()));
    offset += g.f.size();
  }
  out.lambda = basis_.every_row(x.tail(k), m);
  if (!basis_.full_rank()) check_dependent_rows(sys, basis_, out.u);
  if (observer) observer->on_solve_end(solve, 0);
  return out;
}

}  // namespace rollsim
