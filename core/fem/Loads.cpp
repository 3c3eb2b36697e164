#include "fem/Loads.h"

#include <cmath>

namespace rollsim {

namespace {
using V3 = Eigen::Vector3d;

V3 node_at(const Mesh& m, int n) { return V3(m.nodes[n][0], m.nodes[n][1], m.nodes[n][2]); }

// Consistent nodal forces of pressure p on one facet: traction -p n, n the outward normal.
void add_facet_pressure(const Mesh& m, const Facet& f, double p, Eigen::VectorXd& F) {
  const int* conn = m.element(f.element);
  const auto local = facet_local_nodes(m.type, f.local);
  const int d = m.dim;
  if (d == 2) {
    const V3 a = node_at(m, conn[local[0]]), b = node_at(m, conn[local[1]]);
    const V3 n_len(b.y() - a.y(), -(b.x() - a.x()), 0.0);  // outward normal times edge length
    for (int k : {0, 1})
      for (int c = 0; c < 2; ++c) F[conn[local[k]] * 2 + c] += -p * n_len[c] / 2.0;
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
    const V3 n_area = dxs.cross(dxt);  // outward for the right-handed facet ordering
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) F[conn[local[k]] * 3 + c] += -p * N[k] * n_area[c];
  }
}
}  // namespace

Eigen::VectorXd external_nodal_load(const Model& model, int b) {
  const Mesh& m = model.bodies[b].mesh;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.num_nodes()) * m.dim);
  for (const NodalForce& f : model.forces)
    if (f.body == b)
      for (int n : f.nodes)
        for (int c = 0; c < m.dim; ++c) F[n * m.dim + c] += f.value[c];
  for (const Pressure& p : model.pressures)
    if (p.body == b)
      for (const Facet& facet : m.surfaces.at(p.surface)) add_facet_pressure(m, facet, p.value, F);
  return F;
}

}  // namespace rollsim
