#include "solve/ProjectedCG.h"

#include <cmath>

#include "solve/Factorization.h"

namespace rollsim {

namespace {
/// The projector P = I − G(GᵀG)⁻¹Gᵀ with GᵀG factored once. G is sparse: a floating group's modes touch only its
/// own constraint rows, so in FETI G has a few hundred nonzeros per column out of tens of thousands of rows (3D 40³
/// in 5×5×5 subdomains: 60k multipliers × 750 modes, 360 MB dense); dense, the products with G and Gᵀ made the
/// projection the most expensive part of every CG iteration and GᵀG a 30 GFlop product.
class Projector {
 public:
  explicit Projector(const SparseMatrix& G) : G_(G) {
    if (G.cols() == 0) return;
    const Eigen::MatrixXd GtG = Eigen::MatrixXd(SparseMatrix(G.transpose() * G));
    qr_.compute(GtG);
    qr_.setThreshold(1e-10);
    if (qr_.rank() < GtG.cols())
      throw SingularMatrix("GᵀG is singular: the constraints do not hold every rigid mode", -1);
  }
  Eigen::VectorXd apply(const Eigen::VectorXd& w) const {
    return G_.cols() == 0 ? w : Eigen::VectorXd(w - G_ * coarse(G_.transpose() * w));
  }
  /// (GᵀG)⁻¹ v
  Eigen::VectorXd coarse(const Eigen::VectorXd& v) const { return qr_.solve(v); }

 private:
  const SparseMatrix& G_;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr_;
};

/// `g_max` = max |G_ij|, computed once per solve (G does not change during the iterations)
double constraint_error(const SparseMatrix& G, const Eigen::VectorXd& e, const Eigen::VectorXd& lambda, double g_max) {
  if (G.cols() == 0) return 0;
  // relative to the size of the terms of Gᵀλ (e may be zero: no load on the floating groups)
  const double scale = std::max(e.lpNorm<Eigen::Infinity>(), g_max * lambda.lpNorm<Eigen::Infinity>());
  return (G.transpose() * lambda - e).lpNorm<Eigen::Infinity>() / std::max(scale, 1e-300);
}
}  // namespace

ProjectedCGResult projected_cg(const InterfaceProblem& p, const ProjectedCGOptions& o, AnalysisObserver* observer) {
  SparseMatrix converted;  // a problem that gives G dense
  if (p.Gs.cols() == 0 && p.G.cols() > 0) converted = p.G.sparseView();
  const SparseMatrix& G = p.Gs.cols() ? p.Gs : converted;
  const Projector P(G);
  const double g_max =
      G.nonZeros() ? Eigen::Map<const Eigen::VectorXd>(G.valuePtr(), G.nonZeros()).cwiseAbs().maxCoeff() : 0.0;
  ProjectedCGResult res;
  res.lambda = G.cols() ? Eigen::VectorXd(G * P.coarse(p.e)) : Eigen::VectorXd::Zero(p.b.size());
  Eigen::VectorXd r = p.b - p.F(res.lambda);
  Eigen::VectorXd w = P.apply(r);
  const double w0 = w.norm();
  // round-off floor: a projected residual this small relative to the data is zero (e.g. λ fully fixed by Gᵀλ = e)
  const double floor = 1e-14 * std::max(r.norm(), p.b.norm());
  res.residuals.push_back(w0 > floor ? 1.0 : 0.0);
  res.max_constraint_error = constraint_error(G, p.e, res.lambda, g_max);
  Eigen::VectorXd dir, y_prev;
  double wy_prev = 0;
  res.converged = w0 <= floor;
  while (!res.converged && res.iterations < o.max_iterations) {
    const Eigen::VectorXd y = P.apply(o.preconditioner ? o.preconditioner(w) : w);
    const double wy = w.dot(y);
    dir = res.iterations == 0 ? y : Eigen::VectorXd(y + (wy / wy_prev) * dir);
    const Eigen::VectorXd q = p.F(dir);
    const double curvature = dir.dot(q);
    if (!(wy > 0 && curvature > 0)) break;  // breakdown: F not positive definite on ker Gᵀ (or NaN)
    const double step = wy / curvature;
    res.lambda += step * dir;
    r -= step * q;
    w = P.apply(r);
    wy_prev = wy;
    ++res.iterations;
    const double rel = w.norm() / w0;
    res.residuals.push_back(rel);
    res.max_constraint_error = std::max(res.max_constraint_error, constraint_error(G, p.e, res.lambda, g_max));
    if (observer) observer->on_cg_iteration(o.solve, res.iterations, rel);
    res.converged = rel <= o.tolerance || w.norm() <= floor;
    if (!res.converged && observer && observer->cancel_requested()) {
      res.cancelled = true;  // a safe point: λ is a feasible iterate, r its residual
      break;
    }
  }
  // α = (GᵀG)⁻¹Gᵀ(Fλ − b) = −(GᵀG)⁻¹Gᵀ r
  if (G.cols()) res.alpha = -P.coarse(G.transpose() * r);
  return res;
}

}  // namespace rollsim
