#include "solve/CholmodFactorization.h"

#include <cstdio>
#include <mutex>
#include <utility>
#include <vector>

#include "base/Memory.h"
#include "base/Stopwatch.h"
#include "solve/CholmodView.h"
#include "solve/NodeOrdering.h"
#include "solve/SupernodalSolve.h"

namespace rollsim {

namespace {
/// cholmod_analyze may call METIS (CHOLMOD tries it after AMD when AMD's fill is poor: large 3D subdomains), and
/// METIS 5.1 draws from one process-wide random state (GKlib's Mersenne twister, re-seeded at each call). Two
/// concurrent analyses interleave that state, so the ordering — and with it the factor's round-off — depended on
/// thread timing: `feti --threads 2` gave results differing by ~1e-7 from run to run on the 24³ cube in 2×2×2
/// subdomains. Orderings are computed one at a time; the numeric factorizations and solves stay concurrent.
std::mutex analyze_mutex;
/// Smallest L_jj² / A_jj over the columns of a supernodal LLᵀ factor (the pivots of LDLᵀ against their own diagonal),
/// and the column (in A's numbering) where it occurs.
std::pair<double, int> smallest_pivot_ratio(const cholmod_factor& L, const SparseMatrix& A) {
  const auto* super = static_cast<const int*>(L.super);
  const auto* pi = static_cast<const int*>(L.pi);
  const auto* px = static_cast<const int*>(L.px);
  const auto* x = static_cast<const double*>(L.x);
  const auto* perm = static_cast<const int*>(L.Perm);
  const Eigen::VectorXd diag = A.diagonal();
  std::pair<double, int> worst{1.0, -1};
  for (size_t s = 0; s < L.nsuper; ++s) {
    const int nsrow = pi[s + 1] - pi[s];
    for (int k = super[s]; k < super[s + 1]; ++k) {
      const int jj = k - super[s], col = perm ? perm[k] : k;
      const double ljj = x[px[s] + jj + static_cast<long>(jj) * nsrow];
      const double ratio = diag[col] > 0 ? ljj * ljj / diag[col] : 0.0;
      if (ratio < worst.first) worst = {ratio, col};
    }
  }
  return worst;
}
}  // namespace

CholmodSettings CholmodSettings::cholmod_defaults() {
  CholmodSettings s;
  s.ordering = "automatic";
  return s;
}

CholmodFactorization::CholmodFactorization(CholmodSettings settings) : settings_(std::move(settings)) {
  cholmod_start(&common_);
  for (int i = 0; i < 3; ++i) {
    common_.nrelax[i] = static_cast<size_t>(settings_.nrelax[i]);
    common_.zrelax[i] = settings_.zrelax[i];
  }
  const std::string& o = settings_.ordering;
  if (o != "automatic" && o != "auto" && o != "nodes" && o != "amd" && o != "metis" && o != "nesdis")
    throw std::invalid_argument("unknown CHOLMOD ordering '" + o +
                                "' (valid: auto, automatic, nodes, amd, metis, nesdis)");
  common_.supernodal = CHOLMOD_SUPERNODAL;
  common_.final_ll = 1;
  common_.print = 0;
  common_.error_handler = nullptr;
}

CholmodFactorization::~CholmodFactorization() {
  if (factor_) cholmod_free_factor(&factor_, &common_);
  for (cholmod_dense** d : {&X_, &Y_, &E_})
    if (*d) cholmod_free_dense(d, &common_);
  cholmod_finish(&common_);
}

void CholmodFactorization::analyze(const SparseMatrix& A) {
  Stopwatch t;
  if (factor_) cholmod_free_factor(&factor_, &common_);
  cholmod_sparse s = cholmod_view(A);
  {
    const std::lock_guard<std::mutex> lock(analyze_mutex);
    std::string o = settings_.ordering;
    if (o == "auto") o = mean_node_degree(A) >= CholmodSettings::kNestedDissectionDegree ? "nodes" : "amd";
    common_.nmethods = o == "automatic" ? 0 : 1;  // 0: CHOLMOD's own strategy (it sets its methods itself)
    if (o != "automatic")
      common_.method[0].ordering = o == "nodes"   ? CHOLMOD_GIVEN
                                   : o == "amd"   ? CHOLMOD_AMD
                                   : o == "metis" ? CHOLMOD_METIS
                                                  : CHOLMOD_NESDIS;
    if (o == "nodes") {
      std::vector<int> perm = node_nested_dissection(A);
      factor_ = cholmod_analyze_p(&s, perm.data(), nullptr, 0, &common_);
    } else {
      factor_ = cholmod_analyze(&s, &common_);
    }
  }
  if (!factor_ && common_.status == CHOLMOD_OUT_OF_MEMORY)
    throw OutOfMemory("out of memory in CHOLMOD's analysis of a matrix of " + std::to_string(A.rows()) + " rows", 0);
  if (!factor_) throw std::runtime_error("CHOLMOD analysis failed (status " + std::to_string(common_.status) + ")");
  const int ord = common_.method[common_.selected].ordering;
  stats_.ordering = ord == CHOLMOD_GIVEN     ? "METIS-nodes"
                    : ord == CHOLMOD_METIS   ? "METIS"
                    : ord == CHOLMOD_NESDIS  ? "NESDIS"
                    : ord == CHOLMOD_AMD     ? "AMD"
                    : ord == CHOLMOD_COLAMD  ? "COLAMD"
                    : ord == CHOLMOD_NATURAL ? "natural"
                                             : "other";
  stats_.flops = common_.fl;
  stats_.nnz_factor = common_.lnz;
  stats_.analyze_s += t.seconds();
  check_factor_fits(factor_bytes(), A.rows(), "the Cholesky factor (CHOLMOD's symbolic analysis)");
}

double CholmodFactorization::factor_bytes() const { return common_.lnz * (sizeof(double) + sizeof(int) / 4.0); }

void CholmodFactorization::factorize(const SparseMatrix& A) {
  if (!factor_) analyze(A);
  Stopwatch t;
  cholmod_sparse s = cholmod_view(A);
  cholmod_factorize(&s, factor_, &common_);
  stats_.factorize_s += t.seconds();
  ++stats_.factorizations;
  if (common_.status == CHOLMOD_NOT_POSDEF) {
    // factor_->minor is the column (in CHOLMOD's permuted order) where it failed
    const int* perm = static_cast<const int*>(factor_->Perm);
    const int col = (perm && factor_->minor < factor_->n) ? perm[factor_->minor] : -1;
    throw NotPositiveDefinite("matrix is not positive definite", col);
  }
  if (common_.status == CHOLMOD_OUT_OF_MEMORY)
    throw OutOfMemory("out of memory: the Cholesky factor of " + std::to_string(A.rows()) + " rows needs at least " +
                          gigabytes(factor_bytes()) + " (CHOLMOD could not allocate it)",
                      factor_bytes());
  if (common_.status < CHOLMOD_OK)
    throw std::runtime_error("CHOLMOD factorization failed (status " + std::to_string(common_.status) + ")");
  const auto [ratio, col] = smallest_pivot_ratio(*factor_, A);
  stats_.min_pivot_ratio = ratio;
  if (!(ratio > kMinPivotRatio)) {
    char what[120];
    std::snprintf(what, sizeof what, "pivot %.3g of its diagonal in the Cholesky factor at column %d", ratio, col);
    throw SingularMatrix(what, col);
  }
}

void CholmodFactorization::check_factored() const {
  if (!factor_ || !factor_->is_super || factor_->minor < factor_->n)
    throw std::runtime_error("CHOLMOD solve before a successful supernodal factorization");
}

Eigen::VectorXd CholmodFactorization::solve(const Eigen::VectorXd& b) {
  Stopwatch t;
  check_factored();
  Eigen::VectorXd x = supernodal_solve(*factor_, b, work_);
  stats_.solve_s += t.seconds();
  return x;
}

const double* CholmodFactorization::solve_block(int system, const Eigen::MatrixXd& B) {
  check_factored();
  // cholmod_solve2: level-3 BLAS per supernode over all the columns (faster per column than SupernodalSolve's
  // kernels once there are tens of them), its result and workspace kept for the next call
  cholmod_dense rhs{};
  rhs.nrow = rhs.d = static_cast<size_t>(B.rows());
  rhs.ncol = static_cast<size_t>(B.cols());
  rhs.nzmax = rhs.nrow * rhs.ncol;
  rhs.x = const_cast<double*>(B.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_solve2(system, factor_, &rhs, nullptr, &X_, nullptr, &Y_, &E_, &common_))
    throw std::runtime_error("CHOLMOD solve failed (status " + std::to_string(common_.status) + ")");
  return static_cast<const double*>(X_->x);
}

Eigen::MatrixXd CholmodFactorization::solve_columns(const Eigen::MatrixXd& B) {
  Stopwatch t;
  Eigen::MatrixXd X = Eigen::Map<const Eigen::MatrixXd>(solve_block(CHOLMOD_A, B), B.rows(), B.cols());
  stats_.solve_s += t.seconds();
  return X;
}

Eigen::MatrixXd CholmodFactorization::inverse_quadratic(const Eigen::MatrixXd& E) {
  Stopwatch t;
  check_factored();  // a supernodal factor: only the supernodes each column reaches
  Eigen::MatrixXd out = supernodal_inverse_quadratic(*factor_, E);
  stats_.solve_s += t.seconds();
  return out;
}

}  // namespace rollsim
