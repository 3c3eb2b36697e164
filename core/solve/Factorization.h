#pragma once
// One interface for a sparse symmetric factorization A = L D L^T / L L^T:
// analyze (ordering, symbolic fill) once per pattern, factorize per set of values, solve many times.
#include <Eigen/Sparse>
#include <memory>
#include <stdexcept>
#include <string>

namespace rollsim {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

struct FactorStats {
  std::string ordering;                                // e.g. "RCM", "AMD", "METIS"
  double nnz_factor = 0;                               // stored entries of L (skyline: profile incl. diagonal)
  double flops = 0;                                    // floating-point operations of one numeric factorization
  double analyze_s = 0, factorize_s = 0, solve_s = 0;  // accumulated wall times
  long factorizations = 0;
};

/// Thrown when a pivot is zero or (for Cholesky) not positive. `column` is in the caller's numbering.
struct SingularMatrix : std::runtime_error {
  SingularMatrix(const std::string& what, int col) : std::runtime_error(what), column(col) {}
  int column;
};

class Factorization {
 public:
  virtual ~Factorization() = default;
  /// A is square, symmetric, both triangles stored.
  virtual void analyze(const SparseMatrix& A) = 0;
  virtual void factorize(const SparseMatrix& A) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) = 0;
  virtual const FactorStats& stats() const = 0;
};

/// "skyline" (active-column LDL^T with reverse Cuthill-McKee) or "cholmod" (supernodal Cholesky).
/// `trailing` > 0: the last rows are Lagrange multipliers (a symmetric indefinite saddle-point matrix):
/// the skyline keeps them last; "cholmod" then hands the matrix to UMFPACK's LU with partial pivoting,
/// which is safe for it even when a body's stiffness block is singular (a floating body).
std::unique_ptr<Factorization> make_factorization(const std::string& kind, int trailing = 0);

}  // namespace rollsim
