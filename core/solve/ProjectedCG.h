#pragma once
// Projected conjugate gradients on the interface problem (paper eqs. (7)-(8)):
//   F λ − G α = b,   Gᵀ λ = e,
// minimising ½ λᵀFλ − λᵀb subject to Gᵀλ = e: start from λ0 = QG(GᵀQG)⁻¹e, project every residual with
// Pᵀ = I − G(GᵀQG)⁻¹(QG)ᵀ and every search direction with P = I − QG(GᵀQG)⁻¹Gᵀ (GᵀQG factored once), recover
// α = (GᵀQG)⁻¹(QG)ᵀ(Fλ − b). Q = I is the paper's (Euclidean) projector; FETI with a preconditioner may pass
// QG = M⁻¹G, the projector of Farhat–Roux / Klawonn–Widlund, which keeps the coarse correction in the
// preconditioner's metric (measured: 3D 24³ Dirichlet 30 → 24 iterations at 4×4×4, docs/BENCHMARKS-FETI.md).
// With no rigid modes (G empty) it is plain CG on F λ = b (paper eq. (2)). Used by `mixed` and `feti`.
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "base/Observer.h"
#include "base/RunStatus.h"
#include "solve/Factorization.h"

namespace rollsim {

using LinearOperator = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct InterfaceProblem {
  LinearOperator F;   // λ ↦ F λ, symmetric positive semi-definite, positive definite on ker Gᵀ
  Eigen::VectorXd b;  // right-hand side
  Eigen::MatrixXd G;  // multipliers × rigid modes (0 columns: no floating group) …
  SparseMatrix Gs;    // … or the same as a sparse matrix (used when it has columns; FETI: G is very sparse)
  Eigen::VectorXd e;  // one entry per rigid mode
  const SparseMatrix* QG = nullptr;  // Q G for a weighted projector (same shape as G, kept by the caller); null: Q = I
  // G̃ = [C_eq,g R_g] of an unsymmetric problem (F = Σ C_g K_g⁺ C_eq,gᵀ, the constraint G̃ᵀλ = e; projected_gmres):
  // empty when it is G
  SparseMatrix Gt;
  bool unsymmetric = false;  // some group's equations take C_eq ≠ C: F is unsymmetric (projected_gmres, not CG)
  // A guess of λ (the last Newton iteration's): the solve starts there, moved onto Gᵀλ = e, when its projected
  // residual is below the least-norm start's — which stays the reference of the relative tolerance, so a guess
  // saves iterations without loosening the answer. Empty: the least-norm start.
  Eigen::VectorXd start;
};

struct ProjectedCGOptions {
  double tolerance = 1e-4;  // on ‖Pᵀ r_k‖ / ‖Pᵀ r_0‖
  int max_iterations = 10000;
  LinearOperator preconditioner;   // z = M⁻¹ w (empty: identity)
  int solve = 1;                   // the linear solve's number, reported with every iteration
  double absolute = 0;             // or on ‖Pᵀ r_k‖ itself (0: none): converged at the larger of the two
  bool relative_to_start = false;  // `tolerance` of the start's residual (the guess's, when it is kept), not of w_0
  double at_most = 0;              // and ‖Pᵀ r_k‖ at most this, whatever the two above allow (0: no bound)
};

struct ProjectedCGResult {
  Eigen::VectorXd lambda, alpha;
  int iterations = 0;
  bool converged = false;
  bool breakdown = false;         // stopped on non-positive curvature or a NaN (F not positive definite on ker Gᵀ)
  bool round_off = false;         // stopped at the round-off floor (1e-14 of the data) above the tolerance
  int extra_iterations = 0;       // iterations only ProjectedCGOptions::at_most asked for (within the tolerance)
  bool cancelled = false;         // the observer asked to stop: λ, α are the last iterate (Gᵀλ = e holds)
  std::vector<double> residuals;  // ‖Pᵀ r_k‖ / ‖Pᵀ r_0‖, k = 0..iterations
  /// Extreme eigenvalues of the (preconditioned, projected) operator estimated from the CG coefficients (the
  /// Lanczos tridiagonal matrix); 0 when fewer than 2 iterations. Their ratio estimates the condition number.
  double lambda_min = 0, lambda_max = 0;
  double max_constraint_error = 0;  // max over iterations of ‖Gᵀλ_k − e‖∞ / max(‖e‖∞, max|G| ‖λ_k‖∞)
};

/// How a CG that did not converge ended, for the user: not_converged with iteration_limit or breakdown, the
/// iterations, the relative residual reached and the tolerance asked for; converged (or cancelled) otherwise.
RunStatus cg_status(const ProjectedCGResult& result, const ProjectedCGOptions& options);

/// Reports every iteration to `observer` (may be null) and stops early when it asks to cancel.
/// With problem.start, residuals[0] is the guess's residual relative to the least-norm start's (below 1).
/// Throws SingularMatrix (column −1) when GᵀQG is singular: the constraints do not hold some rigid mode.
ProjectedCGResult projected_cg(const InterfaceProblem& problem, const ProjectedCGOptions& options,
                               AnalysisObserver* observer = nullptr);

}  // namespace rollsim
