#include "solve/ProjectedGMRES.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "solve/Projector.h"

namespace rollsim {

namespace {
constexpr int kRestart = 200;
/// A pivot of the rotated Hessenberg at this share of the cycle's largest is round-off: the new Krylov direction is
/// a null vector of the projected F, and a triangular solve through it would divide by round-off.
constexpr double kNullPivot = 1e-12;

/// One GMRES cycle's Hessenberg matrix, reduced to upper triangular by Givens rotations as it grows.
struct Hessenberg {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(kRestart + 1, kRestart);
  Eigen::VectorXd g, c = Eigen::VectorXd::Zero(kRestart), s = Eigen::VectorXd::Zero(kRestart);

  explicit Hessenberg(double beta) : g(Eigen::VectorXd::Zero(kRestart + 1)) { g[0] = beta; }
  /// Rotates column j (entries 0..j+1, already filled) and returns the new residual estimate |g_{j+1}|.
  double rotate(int j) {
    for (int i = 0; i < j; ++i) {
      const double a = H(i, j), b = H(i + 1, j);
      H(i, j) = c[i] * a + s[i] * b;
      H(i + 1, j) = -s[i] * a + c[i] * b;
    }
    const double r = std::hypot(H(j, j), H(j + 1, j));
    c[j] = r > 0 ? H(j, j) / r : 1.0;
    s[j] = r > 0 ? H(j + 1, j) / r : 0.0;
    H(j, j) = r, H(j + 1, j) = 0;
    g[j + 1] = -s[j] * g[j];
    g[j] *= c[j];
    return std::abs(g[j + 1]);
  }
  /// y of the least-squares problem over the first k columns.
  Eigen::VectorXd solve(int k) const { return H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k)); }
};
}  // namespace

ProjectedCGResult projected_gmres(const InterfaceProblem& p, const ProjectedCGOptions& o, AnalysisObserver* observer) {
  const SparseMatrix& G = p.Gs;
  const SparseMatrix& Gt = p.Gt.cols() ? p.Gt : p.Gs;
  const Projector P(Gt, &G);  // direction(y) = Π y = y − G(G̃ᵀG)⁻¹G̃ᵀ y; start(e) = G(G̃ᵀG)⁻¹e
  ProjectedCGResult res;
  res.lambda = P.start(p.e, p.b.size());
  Eigen::VectorXd raw = p.b - p.F(res.lambda);
  Eigen::VectorXd r = P.direction(raw);
  const double r0 = r.norm();  // the reference of the relative tolerance, also from a guess (as projected_cg)
  const double floor = 1e-14 * std::max(raw.norm(), p.b.norm());
  if (p.start.size() == p.b.size() && r0 > floor) {
    Eigen::VectorXd guess = P.feasible(p.start, p.e);
    Eigen::VectorXd raw_g = p.b - p.F(guess);
    Eigen::VectorXd rg = P.direction(raw_g);
    if (rg.norm() < r0) res.lambda = std::move(guess), raw = std::move(raw_g), r = std::move(rg);
  }
  res.residuals.push_back(r0 > floor ? r.norm() / r0 : 0.0);
  // the relative tolerance (of the start's residual, when asked), or the absolute one, as a residual relative to r0
  const double relaxed =
      std::max(o.tolerance * (o.relative_to_start ? res.residuals[0] : 1.0), r0 > 0 ? o.absolute / r0 : 0.0);
  const double tolerance = o.at_most > 0 && r0 > 0 ? std::min(relaxed, o.at_most / r0) : relaxed;
  res.converged = r0 <= floor || res.residuals[0] <= tolerance;
  while (!res.converged && !res.breakdown && !res.cancelled && res.iterations < o.max_iterations) {
    const double beta = r.norm();
    Hessenberg h(beta);
    double largest_pivot = 0;
    bool null_space = false;
    std::vector<Eigen::VectorXd> V{r / beta}, Z;
    int k = 0;
    for (; k < kRestart && res.iterations < o.max_iterations; ++k) {
      res.extra_iterations += res.residuals.back() <= relaxed;  // on only for the constraints' bound
      Z.push_back(o.preconditioner ? P.direction(o.preconditioner(V[k])) : V[k]);
      Eigen::VectorXd w = P.direction(p.F(Z[k]));
      for (int i = 0; i <= k; ++i) {
        h.H(i, k) = w.dot(V[i]);
        w -= h.H(i, k) * V[i];
      }
      h.H(k + 1, k) = w.norm();
      const double next = h.H(k + 1, k);
      const double rel = h.rotate(k) / r0;
      largest_pivot = std::max(largest_pivot, std::abs(h.H(k, k)));
      if (std::abs(h.H(k, k)) <= kNullPivot * largest_pivot) {  // Z_k reached F's null space: the cycle ends before it
        null_space = true;
        break;
      }
      ++res.iterations;
      res.residuals.push_back(rel);
      if (observer) observer->on_cg_iteration(o.solve, res.iterations, rel);
      if (!std::isfinite(rel)) {
        res.breakdown = true;
        break;
      }
      if (rel <= tolerance || next <= 1e-14 * beta) {  // converged, or the Krylov space is exhausted
        ++k;
        break;
      }
      V.push_back(w / next);
      if (observer && observer->cancel_requested()) {
        res.cancelled = true;
        ++k;
        break;
      }
    }
    if (res.breakdown) break;
    const Eigen::VectorXd y = h.solve(k);
    for (int i = 0; i < k; ++i) res.lambda += y[i] * Z[i];
    raw = p.b - p.F(res.lambda);
    r = P.direction(raw);
    res.residuals.back() = r.norm() / r0;  // the true residual at the cycle's end
    res.converged = res.residuals.back() <= tolerance;
    // below the floor, or F singular on the projected space and the data not quite in its range (a multiplier that
    // no dof carries, a kernel mode kept at round-off): no iterate gets closer, the best one is the answer
    if (!res.converged && (r.norm() <= floor || null_space)) res.round_off = true;
    if (res.converged || res.round_off) res.cancelled = false;
    if (res.round_off) break;
  }
  res.alpha = P.amplitudes_unsymmetric(raw);
  return res;
}

}  // namespace rollsim
