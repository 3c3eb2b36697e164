#include "fem/Loads.h"

#include "fem/SolidElement.h"

#include <cmath>

namespace rollsim {

namespace {
using V3 = Eigen::Vector3d;

/// Node n's position: where the mesh puts it, moved by u (every node's dofs) when u is given.
V3 node_at(const Mesh& m, int n, const Eigen::VectorXd* u = nullptr) {
  V3 x(m.nodes[n][0], m.nodes[n][1], m.nodes[n][2]);
  if (u)
    for (int c = 0; c < m.dim; ++c) x[c] += (*u)[static_cast<Eigen::Index>(n) * m.dim + c];
  return x;
}

/// A quadrilateral facet at one of its 2×2 Gauss points g: the shape functions N and their derivatives N,ξ N,η at its
/// corners, and the tangents x,ξ x,η of the facet through the corners x (x,ξ × x,η: the outward normal times the area
/// the point stands for).
struct FacetPoint {
  double N[4], Ns[4], Nt[4];
  V3 dxs = V3::Zero(), dxt = V3::Zero();
  FacetPoint(const V3 (&x)[4], int g) {
    static const double q = 1.0 / std::sqrt(3.0), xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};
    const double s = q * xi[g], t = q * eta[g];
    for (int k = 0; k < 4; ++k) {
      N[k] = 0.25 * (1 + xi[k] * s) * (1 + eta[k] * t);
      Ns[k] = 0.25 * xi[k] * (1 + eta[k] * t);
      Nt[k] = 0.25 * eta[k] * (1 + xi[k] * s);
      dxs += Ns[k] * x[k];
      dxt += Nt[k] * x[k];
    }
  }
};

/// Consistent nodal forces of a load on one facet: at each quadrature point the traction `traction(n)` (n the outward
/// normal times the area — or length — it stands for) is spread over the facet's nodes by their shape functions. The
/// facet is taken where the mesh puts it, or moved by `u` (every node's dofs) when given.
template <class Traction>
void add_facet_load(const Mesh& m, const Facet& f, const Traction& traction, Eigen::VectorXd& F,
                    const Eigen::VectorXd* u = nullptr) {
  const int* conn = m.element(f.element);
  const auto local = facet_local_nodes(m.type, f.local);
  const int d = m.dim;
  if (d == 2) {
    const V3 a = node_at(m, conn[local[0]], u), b = node_at(m, conn[local[1]], u);
    const V3 t = traction(V3(b.y() - a.y(), -(b.x() - a.x()), 0.0));  // outward normal times edge length
    for (int k : {0, 1})
      for (int c = 0; c < 2; ++c) F[conn[local[k]] * 2 + c] += t[c] / 2.0;
    return;
  }
  V3 x[4];
  for (int k = 0; k < 4; ++k) x[k] = node_at(m, conn[local[k]], u);
  for (int g = 0; g < 4; ++g) {
    const FacetPoint at(x, g);
    const V3 load = traction(at.dxs.cross(at.dxt));  // outward for the right-handed facet ordering
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) F[conn[local[k]] * 3 + c] += at.N[k] * load[c];
  }
}

/// Consistent nodal forces of a uniform body force b on every element of `m`: b ∫ N_a dV on each node a.
template <int D>
void add_body_force(const Mesh& m, const V3& b, Eigen::VectorXd& F) {
  typename SolidElement<D>::Coords x;
  for (int e = 0; e < m.num_elements(); ++e) {
    const int* conn = m.element(e);
    for (int a = 0; a < SolidElement<D>::NN; ++a)
      for (int k = 0; k < D; ++k) x(k, a) = m.nodes[static_cast<size_t>(conn[a])][static_cast<size_t>(k)];
    const auto share = SolidElement<D>::shape_integrals(x);
    for (int a = 0; a < SolidElement<D>::NN; ++a)
      for (int k = 0; k < D; ++k) F[conn[a] * D + k] += share[a] * b[k];
  }
}
}  // namespace

Eigen::VectorXd traction_nodal_load(const Mesh& m, const Traction& t) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.num_nodes()) * m.dim);
  const V3 value(t.value[0], t.value[1], t.value[2]);
  for (const Facet& facet : m.surfaces.at(t.surface))
    add_facet_load(
        m, facet, [&](const V3& n_area) -> V3 { return value * n_area.norm(); }, F);
  return F;
}

Eigen::VectorXd surface_node_areas(const Mesh& m, const std::vector<Facet>& facets, const Eigen::VectorXd* u) {
  // the facets' load of a unit pressure along x whatever their normal: |n| dA spread by the shape functions
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.num_nodes()) * m.dim);
  for (const Facet& f : facets)
    add_facet_load(
        m, f, [](const V3& n) { return V3(n.norm(), 0, 0); }, F, u);
  Eigen::VectorXd areas(m.num_nodes());
  for (int n = 0; n < m.num_nodes(); ++n) areas[n] = F[static_cast<Eigen::Index>(n) * m.dim];
  return areas;
}

Eigen::VectorXd external_nodal_load(const Model& model, int b) {
  const Mesh& m = model.bodies[b].mesh;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.num_nodes()) * m.dim);
  for (const NodalForce& f : model.forces)
    if (f.body == b)
      for (int n : f.nodes)
        for (int c = 0; c < m.dim; ++c) F[n * m.dim + c] += f.value[c];
  for (const Pressure& p : model.pressures)
    if (p.body == b && !p.follower)
      for (const Facet& facet : m.surfaces.at(p.surface))
        add_facet_load(
            m, facet, [&](const V3& n_area) -> V3 { return -p.value * n_area; }, F);
  for (const Traction& t : model.tractions)
    if (t.body == b) F += traction_nodal_load(m, t);
  for (const BodyForce& f : model.body_forces)
    if (f.body == b) {
      const V3 value(f.value[0], f.value[1], f.value[2]);
      m.dim == 2 ? add_body_force<2>(m, value, F) : add_body_force<3>(m, value, F);
    }
  return F;
}

std::vector<FollowerPressure> follower_pressures(const Model& model, int b) {
  std::vector<FollowerPressure> out;
  for (const Pressure& p : model.pressures)
    if (p.body == b && p.follower) out.push_back({p.value, model.bodies[b].mesh.surfaces.at(p.surface)});
  return out;
}

Eigen::VectorXd follower_nodal_load(const Mesh& m, const std::vector<FollowerPressure>& loads,
                                    const Eigen::VectorXd& u) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.num_nodes()) * m.dim);
  for (const FollowerPressure& p : loads)
    for (const Facet& facet : p.facets)
      add_facet_load(
          m, facet, [&](const V3& n_area) -> V3 { return -p.value * n_area; }, F, &u);
  return F;
}

Eigen::MatrixXd follower_facet_stiffness(const Mesh& m, const Facet& f, double p, const Eigen::VectorXd& u) {
  const int d = m.dim, nn = m.nodes_per_elem();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nn * d, nn * d);
  const int* conn = m.element(f.element);
  const auto local = facet_local_nodes(m.type, f.local);
  if (d == 2) {  // f_a = f_b = −p/2 (y_b − y_a, x_a − x_b)
    const int a = local[0], b = local[1];
    for (int r : {a, b}) {
      K(r * 2, a * 2 + 1) += 0.5 * p, K(r * 2, b * 2 + 1) -= 0.5 * p;
      K(r * 2 + 1, a * 2) -= 0.5 * p, K(r * 2 + 1, b * 2) += 0.5 * p;
    }
    return K;
  }
  auto skew = [](const V3& v) {
    Eigen::Matrix3d S;
    S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return S;
  };
  V3 x[4];
  for (int k = 0; k < 4; ++k) x[k] = node_at(m, conn[local[k]], &u);
  for (int g = 0; g < 4; ++g) {  // f_a = −p Σ_g N_a (x,ξ × x,η): ∂/∂x_b = −p N_a (N_b,η [x,ξ]× − N_b,ξ [x,η]×)
    const FacetPoint at(x, g);
    const Eigen::Matrix3d Ss = skew(at.dxs), St = skew(at.dxt);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        K.block<3, 3>(local[i] * 3, local[j] * 3) -= p * at.N[i] * (at.Nt[j] * Ss - at.Ns[j] * St);
  }
  return K;
}

}  // namespace rollsim
