#pragma once
// Projected conjugate gradients on the interface problem (paper eqs. (7)-(8)):
//   F λ − G α = b,   Gᵀ λ = e,
// minimising ½ λᵀFλ − λᵀb subject to Gᵀλ = e: start from λ0 = G(GᵀG)⁻¹e, project every residual with
// P = I − G(GᵀG)⁻¹Gᵀ (GᵀG factored once), recover α = (GᵀG)⁻¹Gᵀ(Fλ − b). With no rigid modes (G empty)
// it is plain CG on F λ = b (paper eq. (2)). Used by `mixed` (bodies) and `feti` (subdomains).
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "analysis/Observer.h"
#include "solve/Factorization.h"

namespace rollsim {

using LinearOperator = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct InterfaceProblem {
  LinearOperator F;   // λ ↦ F λ, symmetric positive semi-definite, positive definite on ker Gᵀ
  Eigen::VectorXd b;  // right-hand side
  Eigen::MatrixXd G;  // multipliers × rigid modes (0 columns: no floating group) …
  SparseMatrix Gs;    // … or the same as a sparse matrix (used when it has columns; FETI: G is very sparse)
  Eigen::VectorXd e;  // one entry per rigid mode
};

struct ProjectedCGOptions {
  double tolerance = 1e-4;  // on ‖P r_k‖ / ‖P r_0‖
  int max_iterations = 10000;
  LinearOperator preconditioner;  // z = M⁻¹ w (empty: identity)
  int solve = 1;                  // the linear solve's number, reported with every iteration
};

struct ProjectedCGResult {
  Eigen::VectorXd lambda, alpha;
  int iterations = 0;
  bool converged = false;
  bool cancelled = false;         // the observer asked to stop: λ, α are the last iterate (Gᵀλ = e holds)
  std::vector<double> residuals;  // ‖P r_k‖ / ‖P r_0‖, k = 0..iterations
  double max_constraint_error = 0;  // max over iterations of ‖Gᵀλ_k − e‖∞ / max(‖e‖∞, max|G| ‖λ_k‖∞)
};

/// Reports every iteration to `observer` (may be null) and stops early when it asks to cancel.
/// Throws SingularMatrix (column −1) when GᵀG is singular: the constraints do not hold some rigid mode.
ProjectedCGResult projected_cg(const InterfaceProblem& problem, const ProjectedCGOptions& options,
                               AnalysisObserver* observer = nullptr);

}  // namespace rollsim
