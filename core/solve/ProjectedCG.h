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

namespace rollsim {

using LinearOperator = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct InterfaceProblem {
  LinearOperator F;   // λ ↦ F λ, symmetric positive semi-definite, positive definite on ker Gᵀ
  Eigen::VectorXd b;  // right-hand side
  Eigen::MatrixXd G;  // multipliers × rigid modes (0 columns: no floating group)
  Eigen::VectorXd e;  // one entry per rigid mode
};

struct ProjectedCGOptions {
  double tolerance = 1e-4;  // on ‖P r_k‖ / ‖P r_0‖
  int max_iterations = 10000;
  LinearOperator preconditioner;  // z = M⁻¹ w (empty: identity)
};

struct ProjectedCGResult {
  Eigen::VectorXd lambda, alpha;
  int iterations = 0;
  bool converged = false;
  std::vector<double> residuals;  // ‖P r_k‖ / ‖P r_0‖, k = 0..iterations
  double max_constraint_error = 0;  // max over iterations of ‖Gᵀλ_k − e‖∞ / max(‖e‖∞, max|G| ‖λ_k‖∞)
};

/// Throws SingularMatrix (column −1) when GᵀG is singular: the constraints do not hold some rigid mode.
ProjectedCGResult projected_cg(const InterfaceProblem& problem, const ProjectedCGOptions& options,
                               AnalysisObserver* observer = nullptr);

}  // namespace rollsim
