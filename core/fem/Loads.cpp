#include "fem/Loads.h"

#include "fem/SolidElement.h"

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
    if (f.body == b) {
      const V3 value(f.value[0], f.value[1], f.value[2]);
      m.dim == 2 ? add_body_force<2>(m, value, F) : add_body_force<3>(m, value, F);
    }
  return F;
}

}  // namespace rollsim
