#pragma once
// One interface for a sparse symmetric factorization A = L D L^T / L L^T:
// analyze (ordering, symbolic fill) once per pattern, factorize per set of values, solve many times.
#include <Eigen/Sparse>
#include <memory>
#include <stdexcept>
#include <string>

#include "solve/SolveStats.h"

namespace rollsim {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Smallest pivot a positive definite factorization accepts, relative to its column's own diagonal. Every pivot d_j
/// is at least λ_min(A) and every A_jj at most λ_max(A), so d_j / A_jj below 1e-12 means a condition number above
/// 1e12 — fewer than 4 of double precision's 16 digits left in the solution: singular to working precision
/// (a body or mechanism held by nothing, a near-incompressible material without B-bar, stiffnesses 1e12 apart).
constexpr double kMinPivotRatio = 1e-12;

/// Thrown when a pivot is zero, (for Cholesky) not positive, or below kMinPivotRatio of its diagonal. `column` is in
/// the caller's numbering (−1: unknown).
struct SingularMatrix : std::runtime_error {
  SingularMatrix(const std::string& what, int col) : std::runtime_error(what), column(col) {}
  int column;
};

/// Thrown when a factorization cannot have the memory it needs: refused before the numeric factorization when the
/// symbolic analysis's size exceeds what this process can still take (base/Memory.h), or reported by the library.
/// `bytes`: what it asked for (0: unknown).
struct OutOfMemory : std::runtime_error {
  OutOfMemory(const std::string& what, double asked) : std::runtime_error(what), bytes(asked) {}
  double bytes;
};

/// Throws OutOfMemory when a factor of `bytes` (of a matrix of `rows` rows; `what`: which factor, for the message)
/// cannot fit in what this process can still take.
void check_factor_fits(double bytes, long rows, const std::string& what);

class Factorization {
 public:
  virtual ~Factorization() = default;
  /// A is square, symmetric, both triangles stored.
  virtual void analyze(const SparseMatrix& A) = 0;
  virtual void factorize(const SparseMatrix& A) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) = 0;
  /// X = A⁻¹ B for many right-hand sides at once (by default one solve per column).
  virtual Eigen::MatrixXd solve_columns(const Eigen::MatrixXd& B);
  /// Eᵀ A⁻¹ E (by default Eᵀ solve_columns(E); a Cholesky factor does it with half the triangular solves).
  virtual Eigen::MatrixXd inverse_quadratic(const Eigen::MatrixXd& E);
  virtual const FactorStats& stats() const = 0;
};

/// "skyline" (active-column LDL^T with reverse Cuthill-McKee) or "cholmod" (supernodal Cholesky).
/// `trailing` > 0: the last rows are Lagrange multipliers (a symmetric indefinite saddle-point matrix):
/// the skyline keeps them last; "cholmod" then hands the matrix to UMFPACK's LU with partial pivoting,
/// which is safe for it even when a body's stiffness block is singular (a floating body).
std::unique_ptr<Factorization> make_factorization(const std::string& kind, int trailing = 0);

}  // namespace rollsim
