#include "fem/Loads.h"

#include <cmath>

namespace rollsim {

namespace {
using V3 = Eigen::Vector3d;

V3 node_at(const Mesh& m, int n) { return V3(m.nodes[n][0], m.nodes[n][1], m.nodes[n][2]); }

/// Consistent nodal forces of a load on one facet: at each quadrature point the traction `traction(n)` (n the outward
/// normal times the area — or length — it stands for) is spread over the facet's nodes by their shape functions.
template <class Traction>
void add_facet_load(const Mesh& m, const Facet& f, const Traction& traction, Eigen::VectorXd& F) {
  const int* conn = m.element(f.element);
  const auto local = facet_local_nodes(m.type, f.local);
  const int d = m.dim;
  if (d == 2) {
    const V3 a = node_at(m, conn[local[0]]), b = node_at(m, conn[local[1]]);
    const V3 t = traction(V3(b.y() - a.y(), -(b.x() - a.x()), 0.0));  // outward normal times edge length
    for (int k : {0, 1})
      for (int c = 0; c < 2; ++c) F[conn[local[k]] * 2 + c] += t[c] / 2.0;
    return;
  }
  const double q = 1.0 / std::sqrt(3.0);
  const double xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};
  V3 x[4];
  for (int k = 0; k < 4; ++k) x[k] = node_at(m, conn[local[k]]);
  for (int g = 0; g < 4; ++g) {
    const double s = q * xi[g], t = q * eta[g];
    V3 dxs = V3::Zero(), dxt = V3::Zero();
    double N[4];
    for (int k = 0; k < 4; ++k) {
      N[k] = 0.25 * (1 + xi[k] * s) * (1 + eta[k] * t);
      dxs += 0.25 * xi[k] * (1 + eta[k] * t) * x[k];
      dxt += 0.25 * eta[k] * (1 + xi[k] * s) * x[k];
    }
    const V3 load = traction(dxs.cross(dxt));  // outward for the right-handed facet ordering
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) F[conn[local[k]] * 3 + c] += N[k] * load[c];
  }
}

/// Consistent nodal forces of a uniform body force b on one element: ∫ N b dV by 2×2 (2×2×2) Gauss points.
void add_element_body_force(const Mesh& m, int e, const V3& b, Eigen::VectorXd& F) {
  const int* conn = m.element(e);
  const int d = m.dim, nen = m.nodes_per_elem();
  const double q = 1.0 / std::sqrt(3.0);
  static const double corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int g = 0; g < nen; ++g) {
    const double p[3] = {q * corner[g][0], q * corner[g][1], d == 3 ? q * corner[g][2] : 0.0};
    Eigen::Matrix3d J = Eigen::Matrix3d::Identity();  // dx/dξ (the z row stays identity in 2D)
    J.topLeftCorner(d, d).setZero();
    std::array<double, 8> N{};
    for (int k = 0; k < nen; ++k) {
      double dN[3], n = d == 3 ? 0.125 : 0.25;
      for (int a = 0; a < d; ++a) n *= 1 + corner[k][a] * p[a];
      N[static_cast<size_t>(k)] = n;
      for (int a = 0; a < d; ++a) {
        dN[a] = d == 3 ? 0.125 : 0.25;
        for (int c = 0; c < d; ++c) dN[a] *= c == a ? corner[k][c] : 1 + corner[k][c] * p[c];
      }
      const V3 x = node_at(m, conn[k]);
      for (int r = 0; r < d; ++r)
        for (int a = 0; a < d; ++a) J(r, a) += x[r] * dN[a];
    }
    const double volume = J.determinant();  // the Gauss weights are 1
    for (int k = 0; k < nen; ++k)
      for (int c = 0; c < d; ++c) F[conn[k] * d + c] += N[static_cast<size_t>(k)] * b[c] * volume;
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

Eigen::VectorXd external_nodal_load(const Model& model, int b) {
  const Mesh& m = model.bodies[b].mesh;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.num_nodes()) * m.dim);
  for (const NodalForce& f : model.forces)
    if (f.body == b)
      for (int n : f.nodes)
        for (int c = 0; c < m.dim; ++c) F[n * m.dim + c] += f.value[c];
  for (const Pressure& p : model.pressures)
    if (p.body == b)
      for (const Facet& facet : m.surfaces.at(p.surface))
        add_facet_load(
            m, facet, [&](const V3& n_area) -> V3 { return -p.value * n_area; }, F);
  for (const Traction& t : model.tractions)
    if (t.body == b) F += traction_nodal_load(m, t);
  for (const BodyForce& f : model.body_forces)
    if (f.body == b)
      for (int e = 0; e < m.num_elements(); ++e)
        add_element_body_force(m, e, V3(f.value[0], f.value[1], f.value[2]), F);
  return F;
}

}  // namespace rollsim
