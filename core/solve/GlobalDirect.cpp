#include "solve/GlobalDirect.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "solve/SparseCompare.h"

namespace rollsim {

namespace {
using Triplets = std::vector<Eigen::Triplet<double, int>>;

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

/// Paper eq. (1): the groups' K on the diagonal, C and Cᵀ (C_eqᵀ) in the border, multipliers last — only the
/// independent rows `kept` of C (a dependent row would make the matrix singular).
SparseMatrix global_matrix(const BlockSystem& sys, const std::vector<int>& kept) {
  const long n = sys.num_dofs(), m = static_cast<long>(kept.size());
  Triplets t;
  long offset = 0;
  for (const Group& g : sys.groups) {
    add_block(t, g.K, offset, offset, false);
    if (m > 0) {
      add_block(t, select_rows(g.C, kept), n, offset, false);
      add_block(t, select_rows(g.equation_C(), kept), offset, n, true);  // C_eqᵀ: unsymmetric under Coulomb slip
    }
    offset += g.K.rows();
  }
  if (sys.coupling.nonZeros() > 0) add_block(t, sys.coupling, 0, 0, false);  // stiffness joining two groups
  SparseMatrix A(n + m, n + m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}
/// ‖A x − f‖∞ / (‖A‖∞ ‖x‖∞ + ‖f‖∞), the normwise backward error of the solve: round-off (~1e-16) for a stable
/// factorization of a regular matrix. Above 1e-8 the factor does not represent A: a pivot lost to
/// cancellation that the factorization's own tests let through (UMFPACK stops only at an exactly zero pivot).
void check_backward_error(const SparseMatrix& A, const Eigen::VectorXd& x, const Eigen::VectorXd& f) {
  if (!x.allFinite()) return;  // overflow: the caller's check of the results names the magnitudes
  double norm_A = 0;
  for (int j = 0; j < A.outerSize(); ++j) {  // the largest column sum: ‖A‖∞ (‖A‖₁ when A is unsymmetric)
    double sum = 0;
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) sum += std::abs(it.value());
    norm_A = std::max(norm_A, sum);
  }
  const double scale = norm_A * x.lpNorm<Eigen::Infinity>() + f.lpNorm<Eigen::Infinity>();
  const double error = (A * x - f).lpNorm<Eigen::Infinity>() / std::max(scale, 1e-300);
  if (std::isfinite(scale) && !(error <= 1e-8)) {
    char what[160];
    std::snprintf(what, sizeof what,
                  "the direct solve's backward error is %.3g (round-off is ~1e-16): the matrix is singular to working "
                  "precision",
                  error);
    throw SingularMatrix(what, -1);
  }
}

/// How far a dependent row may miss, relative to the largest d or u or to the terms d was computed from
/// (BlockSystem::d_reference). Not round-off alone: four stick rows on three roll dofs (the 3D pass's symmetry plane)
/// ask the roll for four anchors' axial positions, which agree only as well as the iterate that set them — on the
/// pass 48 × 24 × 8, 3.4e-11 mm, where a slack relative to the Newton correction alone (8e-13 mm late in a step)
/// cut `direct`'s steps back eight times at 20 % of its first millimetre while `mixed` ran on. Contradicting
/// constraints (two rows asking different things of the same dofs) miss by the order of d itself.
constexpr double kDependentRowSlack = 1e-6;

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
}  // namespace

GlobalDirect::GlobalDirect(std::string kind) : kind_(std::move(kind)) {}

void GlobalDirect::add_times(const FactorStats& s) {
  earlier_.analyze_s += s.analyze_s;
  earlier_.factorize_s += s.factorize_s;
  earlier_.solve_s += s.solve_s;
  earlier_flops_ += s.flops_total();
}

bool GlobalDirect::factored(const BlockSystem& sys) const {
  if (!factor_ || factored_versions_.size() != sys.groups.size() || !same_matrix(factored_coupling_, sys.coupling))
    return false;
  for (size_t g = 0; g < sys.groups.size(); ++g)
    if (factored_versions_[g] != sys.groups[g].version || !same_matrix(factored_C_[g], sys.groups[g].C) ||
        !same_matrix(factored_C_eq_[g], sys.groups[g].C_eq))
      return false;
  return true;
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
  factored_versions_.clear();
  factored_C_.clear();
  factored_C_eq_.clear();
  factored_coupling_ = sys.coupling;
  factor_->factorize(A);
  for (const Group& g : sys.groups) {
    factored_versions_.push_back(g.version);
    factored_C_.push_back(g.C);
    factored_C_eq_.push_back(g.C_eq);
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
  const bool refactor = !factored(sys);  // the update policy's versions, or constraint rows that changed
  if (refactor) {
    basis_ = independent_rows(stacked_constraints(sys));
    if (!single) global_ = global_matrix(sys, basis_.kept);
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
  check_backward_error(A, x, f);
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
  out.lambda = Eigen::VectorXd::Zero(m);  // a dependent row's share of the force goes to the rows it depends on…
  for (long i = 0; i < k; ++i) out.lambda[basis_.kept[static_cast<size_t>(i)]] = x[n + i];
  out.lambda = basis_.minimum_norm(out.lambda);  // …then spread as the interface CG spreads it
  if (!basis_.full_rank()) check_dependent_rows(sys, basis_, out.u);
  if (observer) observer->on_solve_end(solve, 0);
  return out;
}

}  // namespace rollsim
