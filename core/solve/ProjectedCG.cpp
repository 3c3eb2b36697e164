#include "solve/ProjectedCG.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "solve/Factorization.h"
#include "solve/Projector.h"

namespace rollsim {

namespace {
/// Extreme eigenvalues of the Lanczos tridiagonal matrix that CG builds implicitly from its step lengths a_k and
/// direction updates b_k (Saad, Iterative Methods, §6.7.3): T_kk = 1/a_k + b_k/a_{k−1}, T_k,k+1 = √b_{k+1}/a_k.
std::pair<double, double> lanczos_extremes(const std::vector<double>& a, const std::vector<double>& b) {
  const auto k = static_cast<Eigen::Index>(a.size());
  if (k < 2) return {0, 0};
  Eigen::VectorXd diag(k), off(k - 1);
  for (Eigen::Index i = 0; i < k; ++i) {
    diag[i] = 1.0 / a[i] + (i > 0 ? b[i] / a[i - 1] : 0.0);
    if (i + 1 < k) off[i] = std::sqrt(b[i + 1]) / a[i];
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
  es.computeFromTridiagonal(diag, off, Eigen::EigenvaluesOnly);
  return {es.eigenvalues()[0], es.eigenvalues()[k - 1]};
}

/// `g_max` = max |G_ij|, computed once per solve (G does not change during the iterations)
double constraint_error(const SparseMatrix& G, const Eigen::VectorXd& e, const Eigen::VectorXd& lambda, double g_max) {
  if (G.cols() == 0) return 0;
  // relative to the size of the terms of Gᵀλ (e may be zero: no load on the floating groups)
  const double scale = std::max(e.lpNorm<Eigen::Infinity>(), g_max * lambda.lpNorm<Eigen::Infinity>());
  return (G.transpose() * lambda - e).lpNorm<Eigen::Infinity>() / std::max(scale, 1e-300);
}
}  // namespace

RunStatus cg_status(const ProjectedCGResult& r, const ProjectedCGOptions& o) {
  if (r.converged) return {};
  if (r.cancelled) return {Status::cancelled, Reason::none, "cancelled between CG iterations"};
  char reached[160];
  std::snprintf(reached, sizeof reached, "relative residual %.3g after %d iterations, tolerance %.3g",
                r.residuals.back(), r.iterations, o.tolerance);
  if (r.round_off)
    return {Status::not_converged, Reason::round_off,
            std::string("the interface CG reached the round-off level of its data before the tolerance (") + reached +
                "): ask for a tolerance above it"};
  if (r.breakdown)
    return {Status::not_converged, Reason::breakdown,
            std::string("the interface CG broke down (no positive curvature left: round-off, or an operator that is "
                        "not positive definite) at ") +
                reached};
  return {Status::not_converged, Reason::iteration_limit,
          std::string("the interface CG reached its iteration limit (") + std::to_string(o.max_iterations) + ") at " +
              reached};
}

ProjectedCGResult projected_cg(const InterfaceProblem& p, const ProjectedCGOptions& o, AnalysisObserver* observer) {
  SparseMatrix converted;  // a problem that gives G dense
  if (p.Gs.cols() == 0 && p.G.cols() > 0) converted = p.G.sparseView();
  const SparseMatrix& G = p.Gs.cols() ? p.Gs : converted;
  const Projector P(G, p.QG);
  const double g_max =
      G.nonZeros() ? Eigen::Map<const Eigen::VectorXd>(G.valuePtr(), G.nonZeros()).cwiseAbs().maxCoeff() : 0.0;
  ProjectedCGResult res;
  res.lambda = P.start(p.e, p.b.size());
  Eigen::VectorXd r = p.b - p.F(res.lambda);
  Eigen::VectorXd w = P.residual(r);
  const double w0 = w.norm();
  // round-off floor: a projected residual this small relative to the data is zero (e.g. λ fully fixed by Gᵀλ = e)
  const double floor = 1e-14 * std::max(r.norm(), p.b.norm());
  if (p.start.size() == p.b.size() && w0 > floor) {  // a guess, moved onto Gᵀλ = e: kept when it is closer
    Eigen::VectorXd guess = P.feasible(p.start, p.e);
    Eigen::VectorXd rg = p.b - p.F(guess);
    Eigen::VectorXd wg = P.residual(rg);
    if (wg.norm() < w0) res.lambda = std::move(guess), r = std::move(rg), w = std::move(wg);
  }
  res.residuals.push_back(w0 > floor ? w.norm() / w0 : 0.0);
  const double relaxed = std::max(o.tolerance * (o.relative_to_start ? w.norm() : w0), o.absolute);
  const double target = o.at_most > 0 ? std::min(relaxed, o.at_most) : relaxed;
  res.max_constraint_error = constraint_error(G, p.e, res.lambda, g_max);
  Eigen::VectorXd dir;
  double wy_prev = 0;
  std::vector<double> steps, updates;  // CG's a_k, b_k for the eigenvalue estimate
  res.converged = w0 <= floor || w.norm() <= target;
  while (!res.converged && res.iterations < o.max_iterations) {
    res.extra_iterations += w.norm() <= relaxed;  // on only for the constraints' bound
    const Eigen::VectorXd y = P.direction(o.preconditioner ? o.preconditioner(w) : w);
    const double wy = w.dot(y);
    const double update = res.iterations == 0 ? 0.0 : wy / wy_prev;
    dir = res.iterations == 0 ? y : Eigen::VectorXd(y + update * dir);
    const Eigen::VectorXd q = p.F(dir);
    const double curvature = dir.dot(q);
    if (!(wy > 0 && curvature > 0)) {  // breakdown: F not positive definite on ker Gᵀ (or NaN)
      res.breakdown = true;
      break;
    }
    const double step = wy / curvature;
    steps.push_back(step), updates.push_back(update);
    res.lambda += step * dir;
    r -= step * q;
    w = P.residual(r);
    wy_prev = wy;
    ++res.iterations;
    const double rel = w.norm() / w0;
    res.residuals.push_back(rel);
    res.max_constraint_error = std::max(res.max_constraint_error, constraint_error(G, p.e, res.lambda, g_max));
    if (observer) observer->on_cg_iteration(o.solve, res.iterations, rel);
    res.converged = w.norm() <= target;
    if (!res.converged && w.norm() <= floor) {  // no digit left to gain: the tolerance is below round-off here
      res.round_off = true;
      break;
    }
    if (!res.converged && observer && observer->cancel_requested()) {
      res.cancelled = true;  // a safe point: λ is a feasible iterate, r its residual
      break;
    }
  }
  std::tie(res.lambda_min, res.lambda_max) = lanczos_extremes(steps, updates);
  res.alpha = P.amplitudes(r);
  return res;
}

}  // namespace rollsim
