#include "model/RigidModes.h"

#include <algorithm>
#include <cmath>

#include "model/DofMap.h"

namespace rollsim {

Eigen::MatrixXd rigid_modes(const Mesh& m, const Eigen::VectorXd* u) {
  const int d = m.dim, nmodes = d == 2 ? 3 : 6;
  std::vector<Eigen::Vector3d> at(m.nodes.size());
  for (size_t n = 0; n < at.size(); ++n) {
    at[n] = Eigen::Vector3d(m.nodes[n][0], m.nodes[n][1], m.nodes[n][2]);
    if (u)
      for (int k = 0; k < d; ++k) at[n][k] += (*u)[static_cast<Eigen::Index>(n) * d + k];
  }
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& x : at) c += x;
  c /= std::max(1, m.num_nodes());
  double size = 0;
  for (const Eigen::Vector3d& x : at) size = std::max(size, (x - c).norm());
  if (size == 0) size = 1;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m.num_nodes()) * d, nmodes);
  for (int n = 0; n < m.num_nodes(); ++n) {
    const Eigen::Vector3d x = (at[static_cast<size_t>(n)] - c) / size;
    for (int k = 0; k < d; ++k) R(n * d + k, k) = 1.0;
    if (d == 2) {
      R(n * 2, 2) = -x.y();
      R(n * 2 + 1, 2) = x.x();
      continue;
    }
    for (int axis = 0; axis < 3; ++axis) {  // u = e_axis x x
      const Eigen::Vector3d w = Eigen::Vector3d::Unit(axis).cross(x);
      for (int k = 0; k < 3; ++k) R(n * 3 + k, 3 + axis) = w[k];
    }
  }
  return R;
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
    if (dominant < dim)
      names.push_back(std::string("translation along ") + axes[dominant]);
    else
      names.push_back(std::string("rotation about ") + (dim == 2 ? 'z' : axes[dominant - 3]));
  }
  return names;
}

}  // namespace rollsim
