#include "solve/DenseInterfaceSolve.h"

#include <Eigen/LU>

namespace rollsim {

namespace {
Eigen::MatrixXd modes(const InterfaceProblem& p, bool tilde) {
  if (p.Gs.cols() == 0) return p.G;
  return Eigen::MatrixXd(tilde && p.Gt.cols() ? p.Gt : p.Gs);
}
}  // namespace

ProjectedCGResult dense_interface_solve(const Eigen::MatrixXd& F, const InterfaceProblem& p,
                                        const std::vector<int>& rows) {
  const Eigen::MatrixXd G = modes(p, false), Gt = modes(p, true);
  const auto m = static_cast<Eigen::Index>(rows.size());
  const Eigen::Index r = G.cols();
  // the modes' columns scaled to F's size (lengths × forces against flexibilities), so that partial pivoting
  // weighs both blocks alike; α is scaled back below
  const double gmax = r ? std::max(G.cwiseAbs().maxCoeff(), Gt.cwiseAbs().maxCoeff()) : 0.0;
  const double fmax = F.size() ? F.cwiseAbs().maxCoeff() : 0.0;
  const double scale = gmax > 0 && fmax > 0 ? fmax / gmax : 1.0;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m + r, m + r);
  A.topLeftCorner(m, m) = F(rows, rows);
  A.topRightCorner(m, r) = -scale * G(rows, Eigen::all);
  A.bottomLeftCorner(r, m) = scale * Gt(rows, Eigen::all).transpose();
  Eigen::VectorXd rhs(m + r);
  rhs << p.b(rows), scale * p.e;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  Eigen::VectorXd x = lu.solve(rhs);
  x += lu.solve(rhs - A * x);  // one step of iterative refinement
  ProjectedCGResult out;
  out.lambda = Eigen::VectorXd::Zero(F.rows());
  out.lambda(rows) = x.head(m);
  out.alpha = scale * x.tail(r);
  const Eigen::VectorXd b = p.b(rows), res = b + G(rows, Eigen::all) * out.alpha - F(rows, Eigen::all) * out.lambda;
  const double bn = b.norm();
  out.residuals = {1.0, bn > 0 ? res.norm() / bn : res.norm()};
  if (r) {
    const double en = std::max(p.e.cwiseAbs().maxCoeff(), gmax * out.lambda.cwiseAbs().maxCoeff());
    const double err = (Gt.transpose() * out.lambda - p.e).cwiseAbs().maxCoeff();
    out.max_constraint_error = en > 0 ? err / en : err;
  }
  // NaN fails both comparisons
  out.converged = out.residuals[1] <= kDenseInterfaceResidual && out.max_constraint_error <= kDenseInterfaceResidual;
  out.breakdown = !out.converged;
  return out;
}

}  // namespace rollsim
