#include "model/RigidModes.h"

#include <algorithm>
#include <cmath>

#include "model/DofMap.h"

namespace rollsim {

namespace {
/// Every node's position X (+ u), as 3-vectors.
std::vector<Eigen::Vector3d> positions(const Mesh& m, const Eigen::VectorXd* u) {
  std::vector<Eigen::Vector3d> at(m.nodes.size());
  for (size_t n = 0; n < at.size(); ++n) {
    at[n] = Eigen::Vector3d(m.nodes[n][0], m.nodes[n][1], m.nodes[n][2]);
    if (u)
      for (int k = 0; k < m.dim; ++k) at[n][k] += (*u)[static_cast<Eigen::Index>(n) * m.dim + k];
  }
  return at;
}

ModeFrame frame_of(const std::vector<Eigen::Vector3d>& at) {
  ModeFrame f;
  for (const Eigen::Vector3d& x : at) f.center += x;
  f.center /= std::max<double>(1.0, static_cast<double>(at.size()));
  f.size = 0;
  for (const Eigen::Vector3d& x : at) f.size = std::max(f.size, (x - f.center).norm());
  if (f.size == 0) f.size = 1;
  return f;
}
}  // namespace

ModeFrame mode_frame(const Mesh& mesh) { return frame_of(positions(mesh, nullptr)); }

Eigen::MatrixXd rigid_mode_rows(const Eigen::MatrixXd& x, const Eigen::VectorXi& component, const ModeFrame& frame) {
  const Eigen::Index d = x.cols(), nmodes = d == 2 ? 3 : 6;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(x.rows(), nmodes);
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    Eigen::Vector3d p = -frame.center;
    for (Eigen::Index k = 0; k < d; ++k) p[k] += x(i, k);
    p /= frame.size;
    const int c = component[i];
    R(i, c) = 1.0;
    if (d == 2) {
      R(i, 2) = c == 0 ? -p.y() : p.x();
      continue;
    }
    for (int axis = 0; axis < 3; ++axis) R(i, 3 + axis) = Eigen::Vector3d::Unit(axis).cross(p)[c];  // u = e_axis × x
  }
  return R;
}

Eigen::MatrixXd rigid_modes(const Mesh& m, const Eigen::VectorXd* u) {
  const std::vector<Eigen::Vector3d> at = positions(m, u);
  const int d = m.dim;
  Eigen::MatrixXd x(static_cast<Eigen::Index>(at.size()) * d, d);
  Eigen::VectorXi component(x.rows());
  for (size_t n = 0; n < at.size(); ++n)
    for (int c = 0; c < d; ++c) {
      const Eigen::Index i = static_cast<Eigen::Index>(n) * d + c;
      x.row(i) = at[n].head(d).transpose();
      component[i] = c;
    }
  return rigid_mode_rows(x, component, frame_of(at));
}

namespace {
/// Rows of R at the prescribed dofs: a rigid motion is prevented iff it moves one of them.
Eigen::MatrixXd prescribed_rows(const Eigen::MatrixXd& R, const DofMap& dofs) {
  Eigen::MatrixXd Rc(dofs.num_prescribed(), R.cols());
  for (Eigen::Index i = 0, row = 0; i < R.rows(); ++i)
    if (dofs.equation(static_cast<int>(i / dofs.dim()), static_cast<int>(i % dofs.dim())) < 0) Rc.row(row++) = R.row(i);
  return Rc;
}

/// Orthonormal basis (columns) of the combinations of rigid modes that leave every prescribed dof at rest.
Eigen::MatrixXd free_combinations(const Eigen::MatrixXd& R, const DofMap& dofs) {
  const Eigen::MatrixXd Rc = prescribed_rows(R, dofs);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Rc.transpose() * Rc, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  std::vector<Eigen::Index> kept;
  for (Eigen::Index k = 0; k < sv.size(); ++k)
    if (sv[k] <= 1e-10 * std::max(1.0, sv[0])) kept.push_back(k);
  Eigen::MatrixXd V(R.cols(), static_cast<Eigen::Index>(kept.size()));
  for (size_t k = 0; k < kept.size(); ++k) V.col(static_cast<Eigen::Index>(k)) = svd.matrixV().col(kept[k]);
  return V;
}
}  // namespace

Eigen::MatrixXd kernel_basis(const Mesh& mesh, const DofMap& dofs, const Eigen::VectorXd* u) {
  const Eigen::MatrixXd R = rigid_modes(mesh, u);
  const Eigen::MatrixXd V = free_combinations(R, dofs);
  Eigen::MatrixXd Rf(dofs.num_free(), V.cols());
  if (V.cols() == 0) return Rf;
  const Eigen::MatrixXd RV = R * V;
  for (Eigen::Index i = 0; i < R.rows(); ++i) {
    const int eq = dofs.equation(static_cast<int>(i / dofs.dim()), static_cast<int>(i % dofs.dim()));
    if (eq >= 0) Rf.row(eq) = RV.row(i);
  }
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(Rf);
  return qr.householderQ() * Eigen::MatrixXd::Identity(Rf.rows(), Rf.cols());
}

Eigen::MatrixXd stiffness_kernel(const SparseMatrix& K, const Eigen::MatrixXd& R, double tolerance) {
  if (R.cols() == 0 || K.rows() != R.rows()) return R;
  const Eigen::MatrixXd KR = K * R;
  const double scale = K.diagonal().cwiseAbs().maxCoeff();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(KR, Eigen::ComputeThinV);
  std::vector<Eigen::Index> null;
  for (Eigen::Index k = 0; k < svd.singularValues().size(); ++k)
    if (svd.singularValues()[k] <= tolerance * scale) null.push_back(k);
  if (static_cast<Eigen::Index>(null.size()) == R.cols()) return R;
  Eigen::MatrixXd V(R.cols(), static_cast<Eigen::Index>(null.size()));
  for (size_t k = 0; k < null.size(); ++k) V.col(static_cast<Eigen::Index>(k)) = svd.matrixV().col(null[k]);
  return R * V;
}

std::vector<std::string> free_rigid_modes(const Model& model, int b) {
  const Body& body = model.bodies[b];
  const DofMap dofs(body, b, model.displacements);
  const Eigen::MatrixXd V = free_combinations(rigid_modes(body.mesh), dofs);
  const char* axes = "xyz";
  const int dim = body.mesh.dim;
  std::vector<std::string> names;
  for (Eigen::Index k = 0; k < V.cols(); ++k) {
    Eigen::Index dominant = 0;
    V.col(k).cwiseAbs().maxCoeff(&dominant);
    const bool translation = dominant < dim;
    const char axis = translation ? axes[dominant] : (dim == 2 ? 'z' : axes[dominant - 3]);
    std::string name = translation ? "translation along " : "rotation about ";
    name += axis;
    names.push_back(name);
  }
  return names;
}

}  // namespace rollsim
