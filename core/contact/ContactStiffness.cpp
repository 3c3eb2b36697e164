#include "contact/ContactStiffness.h"

namespace rollsim {

namespace {
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix15 = Eigen::Matrix<double, 15, 15>;
using Matrix3x15 = Eigen::Matrix<double, 3, 15>;
using Matrix2x15 = Eigen::Matrix<double, 2, 15>;

Eigen::Vector3d position(const Model& model, int body, int node, const std::vector<Eigen::VectorXd>& u) {
  const auto& X = model.bodies[body].mesh.nodes[node];
  const int dim = model.dim;
  Eigen::Vector3d x(X[0], X[1], X[2]);
  for (int k = 0; k < dim; ++k) x[k] += u[body][dim * node + k];
  return x;
}

/// Whether a row's point holds its master point (ξ): a sticking point, or a projection clamped to the facet's border.
bool held(const ContactPair& p, const PairState& s, const ConstraintRow& row, bool inside) {
  const bool stuck = frictional(p.kind) && !s.slip[row.point];
  return row.comp >= 0 || stuck || !inside;
}

/// [v_s; −(1 − ξ) v; −ξ v] over (slave, a, b): a row's coefficients along v.
Vector6 spread(const Eigen::Vector2d& v, double xi) {
  Vector6 out;
  out << v, -(1 - xi) * v, -xi * v;
  return out;
}

/// λ ∂C/∂u of one 2D row (header: the formulas), symmetric, over (slave, a, b).
Matrix6 segment_term(const ContactPair& p, const PairState& s, const ConstraintRow& row, double lambda,
                     const Model& model, const std::vector<Eigen::VectorXd>& u) {
  const ContactPoint& c = s.points[row.point];
  const Eigen::Vector2d a = position(model, p.master_body, c.master_nodes[0], u).head<2>();
  const Eigen::Vector2d b = position(model, p.master_body, c.master_nodes[1], u).head<2>();
  const Eigen::Vector2d x = position(model, p.slave_body, c.slave_node, u).head<2>();
  const double l = (b - a).norm(), xi = c.N[1];
  const Eigen::Vector2d t = (b - a) / l, n(t.y(), -t.x());
  Vector6 N0;
  N0 << 0, 0, -n, n;
  const Vector6 D = spread(t, xi);
  if (!held(p, s, row, xi > 0 && xi < 1)) {  // sliding: the Hessian of the gap
    const double g = n.dot(x - (1 - xi) * a - xi * b);
    return -lambda / l * (D * N0.transpose() + N0 * D.transpose()) - lambda * g / (l * l) * N0 * N0.transpose();
  }
  const Matrix6 M = row.comp < 0 ? Matrix6(-D * N0.transpose()) : Matrix6(spread(n, xi) * N0.transpose());
  return 0.5 * lambda / l * (M + M.transpose());
}

/// A bilinear face at a point (ξ, η) in the current configuration, over (slave, x_1 … x_4): the covariant tangents
/// a_α = x_,α, the normal n, the gap g, the metric m_αβ = a_α · a_β, the curvature h_αβ = n · x_,αβ (bilinear: only
/// h_12 = n · x_,ξη), and the operators δr̃ = R δu (δx_s − Σ N_k δx_k, ξ held) and δã_α = A_α δu (Σ N_k,α δx_k).
struct Face {
  Eigen::Vector3d a[2], n;
  double g = 0;
  Eigen::Matrix2d m, h;
  Matrix3x15 R = Matrix3x15::Zero(), A[2] = {Matrix3x15::Zero(), Matrix3x15::Zero()};
  bool inside = false;  // (ξ, η) strictly inside the face: the projection slides freely
};

Face face_at(const ContactPair& p, const ContactPoint& c, const Model& model, const std::vector<Eigen::VectorXd>& u) {
  static const double xi_n[4] = {-1, 1, 1, -1}, eta_n[4] = {-1, -1, 1, 1};
  double xi = 0, eta = 0;  // the isoparametric map reproduces ξ and η from the nodal values
  for (int k = 0; k < 4; ++k) xi += c.N[k] * xi_n[k], eta += c.N[k] * eta_n[k];
  Face f;
  f.a[0].setZero(), f.a[1].setZero();
  Eigen::Vector3d r = position(model, p.slave_body, c.slave_node, u), x_xieta = Eigen::Vector3d::Zero();
  f.R.leftCols<3>().setIdentity();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d x = position(model, p.master_body, c.master_nodes[k], u);
    const double dN[2] = {0.25 * xi_n[k] * (1 + eta_n[k] * eta), 0.25 * eta_n[k] * (1 + xi_n[k] * xi)};
    r -= c.N[k] * x;
    x_xieta += 0.25 * xi_n[k] * eta_n[k] * x;
    f.R.block<3, 3>(0, 3 + 3 * k) = -c.N[k] * Eigen::Matrix3d::Identity();
    for (int al = 0; al < 2; ++al) {
      f.a[al] += dN[al] * x;
      f.A[al].block<3, 3>(0, 3 + 3 * k) = dN[al] * Eigen::Matrix3d::Identity();
    }
  }
  f.n = f.a[0].cross(f.a[1]).normalized();
  f.g = f.n.dot(r);
  f.m << f.a[0].dot(f.a[0]), f.a[0].dot(f.a[1]), f.a[1].dot(f.a[0]), f.a[1].dot(f.a[1]);
  const double h12 = f.n.dot(x_xieta);
  f.h << 0, h12, h12, 0;
  f.inside = std::abs(xi) < 1 && std::abs(eta) < 1;
  return f;
}

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d out;
  out << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return out;
}

/// λ ∂C/∂u of one 3D row (header: the formulas), symmetric, over (slave, x_1 … x_4).
Matrix15 face_term(const ContactPair& p, const PairState& s, const ConstraintRow& row, double lambda,
                   const Model& model, const std::vector<Eigen::VectorXd>& u) {
  const Face f = face_at(p, s.points[row.point], model, u);
  Matrix2x15 Nn, P;  // rows n · δã_α and a_α · δr̃
  for (int al = 0; al < 2; ++al) Nn.row(al) = f.n.transpose() * f.A[al], P.row(al) = f.a[al].transpose() * f.R;
  const Eigen::Matrix2d m_inv = f.m.inverse();
  if (!held(p, s, row, f.inside)) {                                       // sliding: the Hessian of the gap
    const Matrix2x15 dxi = (f.m - f.g * f.h).inverse() * (P + f.g * Nn);  // δξ^α
    const Matrix2x15 B = f.h * dxi + Nn;
    const Matrix15 K =
        -dxi.transpose() * Nn - Nn.transpose() * dxi - dxi.transpose() * f.h * dxi + f.g * B.transpose() * m_inv * B;
    return lambda * K;
  }
  Eigen::Matrix<double, 3, 2> basis;
  basis << f.a[0], f.a[1];
  const Matrix3x15 dn = -basis * m_inv * Nn;  // Δn with ξ held: −a^α (n · Δã_α)
  Matrix15 M;
  if (row.comp < 0) {
    M = f.R.transpose() * dn;
  } else if (row.comp == kSupportedTangent) {
    return Matrix15::Zero();  // along n × e (a supported axis e): its turn is left out
  } else {
    const double l1 = f.a[0].norm();
    const Eigen::Vector3d t1 = f.a[0] / l1;
    const Matrix3x15 dt1 = (Eigen::Matrix3d::Identity() - t1 * t1.transpose()) * f.A[0] / l1;
    const Matrix3x15 dt = row.comp == 0 ? dt1 : Matrix3x15(-cross_matrix(t1) * dn + cross_matrix(f.n) * dt1);
    M = f.R.transpose() * dt;
  }
  return 0.5 * lambda * (M + M.transpose());
}
}  // namespace

std::vector<StiffnessEntry> contact_geometric_stiffness(const Model& model, const std::vector<PairState>& pairs,
                                                        const std::vector<ConstraintRow>& rows,
                                                        const std::vector<int>& kept, const Eigen::VectorXd& lambda,
                                                        const std::vector<Eigen::VectorXd>& u) {
  std::vector<StiffnessEntry> out;
  const int dim = model.dim;
  for (size_t i = 0; i < kept.size(); ++i) {
    const ConstraintRow& row = rows[kept[i]];
    const ContactPair& p = model.contacts[row.pair];
    if (p.kind == ContactKind::Tied || p.sliding != ContactPair::Sliding::Iteration) continue;
    const PairState& s = pairs[row.pair];
    const ContactPoint& c = s.points[row.point];
    const double l = lambda[static_cast<Eigen::Index>(i)];
    const Eigen::MatrixXd K = dim == 2 ? Eigen::MatrixXd(segment_term(p, s, row, l, model, u))
                                       : Eigen::MatrixXd(face_term(p, s, row, l, model, u));
    std::vector<int> body{p.slave_body}, node{c.slave_node};
    for (int n : c.master_nodes) body.push_back(p.master_body), node.push_back(n);
    for (int r = 0; r < K.rows(); ++r)
      for (int q = 0; q < K.cols(); ++q)
        if (K(r, q) != 0)
          out.push_back({body[r / dim], node[r / dim], r % dim, body[q / dim], node[q / dim], q % dim, K(r, q)});
  }
  return out;
}

}  // namespace rollsim
