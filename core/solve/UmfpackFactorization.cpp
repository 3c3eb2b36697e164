#include "solve/UmfpackFactorization.h"

#include <umfpack.h>

#include "base/Memory.h"
#include "base/Stopwatch.h"

namespace rollsim {

UmfpackFactorization::UmfpackFactorization() {
  umfpack_di_defaults(control_);
  control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;  // AMD on A + Aᵀ, diagonal pivots preferred
}

UmfpackFactorization::~UmfpackFactorization() {
  free_numeric();
  if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
}

void UmfpackFactorization::set_refinement_steps(int steps) { control_[UMFPACK_IRSTEP] = steps; }

void UmfpackFactorization::free_numeric() {
  if (numeric_) umfpack_di_free_numeric(&numeric_);
  numeric_ = nullptr;
}

void UmfpackFactorization::analyze(const SparseMatrix& A) {
  Stopwatch t;
  free_numeric();
  if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  A_ = A;
  A_.makeCompressed();
  double info[UMFPACK_INFO];
  const int status = umfpack_di_symbolic(static_cast<int>(A_.rows()), static_cast<int>(A_.cols()), A_.outerIndexPtr(),
                                         A_.innerIndexPtr(), A_.valuePtr(), &symbolic_, control_, info);
  if (status == UMFPACK_ERROR_out_of_memory)
    throw OutOfMemory("out of memory in UMFPACK's analysis of a matrix of " + std::to_string(A_.rows()) + " rows", 0);
  if (status != UMFPACK_OK) throw std::runtime_error("UMFPACK analysis failed (status " + std::to_string(status) + ")");
  stats_.ordering = "AMD (UMFPACK symmetric strategy)";
  stats_.analyze_s += t.seconds();
  factor_bytes_ = info[UMFPACK_NUMERIC_SIZE_ESTIMATE] * info[UMFPACK_SIZE_OF_UNIT];
  check_factor_fits(factor_bytes_, A_.rows(), "the LU factors (UMFPACK's symbolic analysis)");
}

void UmfpackFactorization::factorize(const SparseMatrix& A) {
  if (!symbolic_) analyze(A);
  Stopwatch t;
  A_ = A;
  A_.makeCompressed();
  free_numeric();
  double info[UMFPACK_INFO];
  const int status =
      umfpack_di_numeric(A_.outerIndexPtr(), A_.innerIndexPtr(), A_.valuePtr(), symbolic_, &numeric_, control_, info);
  stats_.factorize_s += t.seconds();
  ++stats_.factorizations;
  if (status == UMFPACK_WARNING_singular_matrix) throw SingularMatrix("matrix is singular", -1);
  if (status == UMFPACK_ERROR_out_of_memory)
    throw OutOfMemory("out of memory: the LU factors of " + std::to_string(A_.rows()) + " rows need at least " +
                          gigabytes(factor_bytes_) + " (UMFPACK could not allocate them)",
                      factor_bytes_);
  if (status != UMFPACK_OK)
    throw std::runtime_error("UMFPACK factorization failed (status " + std::to_string(status) + ")");
  stats_.nnz_factor = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
  stats_.flops = info[UMFPACK_FLOPS];
  rcond_ = info[UMFPACK_RCOND];
}

Eigen::VectorXd UmfpackFactorization::solve(const Eigen::VectorXd& b) {
  if (!numeric_) throw std::logic_error("UmfpackFactorization::solve before factorize");
  Stopwatch t;
  Eigen::VectorXd x(b.size());
  double info[UMFPACK_INFO];
  const int status = umfpack_di_solve(UMFPACK_A, A_.outerIndexPtr(), A_.innerIndexPtr(), A_.valuePtr(), x.data(),
                                      b.data(), numeric_, control_, info);
  if (status != UMFPACK_OK) throw std::runtime_error("UMFPACK solve failed (status " + std::to_string(status) + ")");
  stats_.solve_s += t.seconds();
  refinement_steps_ += static_cast<long>(info[UMFPACK_IR_TAKEN]);
  return x;
}

}  // namespace rollsim
