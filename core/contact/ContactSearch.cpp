#include "contact/ContactSearch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace rollsim {

namespace {
constexpr double kInside = 1e-6;  // parametric tolerance: a projection on a facet's edge belongs to the facet

Eigen::Vector3d point(const Mesh& m, int n) { return {m.nodes[n][0], m.nodes[n][1], m.nodes[n][2]}; }

struct Projection {
  bool inside = false;
  double distance = std::numeric_limits<double>::infinity();
  double depth = 0;  // how far inside the facet, parametrically (0 on its border)
  ContactPoint cp;
};

/// Whether projection p is nearer than b. Distances within `tie` of each other are a tie, which goes to the facet p
/// lies deeper inside, and a tie in that too (a node on the edge two facets share) to the facet found first — so the
/// facet an edge node gets does not follow the round-off of the configuration: the 3D pass's fourth step put node 739
/// on either facet of a roll edge under two Newton paths, normals 3.6° apart, forces 3.4e-5 apart.
bool nearer(const Projection& p, const Projection& b, double tie) {
  if (std::abs(p.distance - b.distance) > tie) return p.distance < b.distance;
  return p.depth > b.depth + kInside;
}

/// 2D: the edge a→b of a counter-clockwise element has its outward normal to the right.
Projection project_on_segment(const Mesh& m, const std::vector<int>& nodes, const Eigen::Vector3d& x) {
  const Eigen::Vector3d a = point(m, nodes[0]), b = point(m, nodes[1]);
  const double length = (b - a).norm();
  const Eigen::Vector3d t = (b - a) / length;
  const double s = (x - a).dot(t) / length;
  Projection p;
  p.inside = s >= -kInside && s <= 1 + kInside;
  p.depth = std::min(s, 1 - s);
  const double sc = std::clamp(s, 0.0, 1.0);
  p.cp.master_nodes = nodes;
  p.cp.N = {1 - sc, sc};
  p.cp.normal = Eigen::Vector3d(t.y(), -t.x(), 0);
  p.cp.tangent[0] = t;
  const Eigen::Vector3d xp = a + sc * (b - a);
  p.cp.separation = x - xp;
  p.cp.gap = p.cp.normal.dot(x - xp);
  p.distance = (x - xp).norm();
  return p;
}

/// 3D: bilinear face, nodes counter-clockwise seen from outside; Newton on the closest-point conditions.
Projection project_on_face(const Mesh& m, const std::vector<int>& nodes, const Eigen::Vector3d& x) {
  std::array<Eigen::Vector3d, 4> X;
  for (int k = 0; k < 4; ++k) X[k] = point(m, nodes[k]);
  static const double xi_n[4] = {-1, 1, 1, -1}, eta_n[4] = {-1, -1, 1, 1};
  double xi = 0, eta = 0;
  Eigen::Vector3d xp, dxi, deta;
  for (int it = 0; it < 20; ++it) {
    xp.setZero(), dxi.setZero(), deta.setZero();
    for (int k = 0; k < 4; ++k) {
      xp += 0.25 * (1 + xi_n[k] * xi) * (1 + eta_n[k] * eta) * X[k];
      dxi += 0.25 * xi_n[k] * (1 + eta_n[k] * eta) * X[k];
      deta += 0.25 * eta_n[k] * (1 + xi_n[k] * xi) * X[k];
    }
    const Eigen::Vector3d r = x - xp;
    Eigen::Matrix2d J;
    J << dxi.dot(dxi), dxi.dot(deta), deta.dot(dxi), deta.dot(deta);
    const Eigen::Vector2d step = J.ldlt().solve(Eigen::Vector2d(dxi.dot(r), deta.dot(r)));
    xi += step[0], eta += step[1];
    if (step.norm() < 1e-13) break;
  }
  Projection p;
  p.inside = std::abs(xi) <= 1 + 2 * kInside && std::abs(eta) <= 1 + 2 * kInside;
  p.depth = std::min(1 - std::abs(xi), 1 - std::abs(eta));
  xi = std::clamp(xi, -1.0, 1.0), eta = std::clamp(eta, -1.0, 1.0);
  xp.setZero(), dxi.setZero(), deta.setZero();
  p.cp.N.resize(4);
  for (int k = 0; k < 4; ++k) {
    p.cp.N[k] = 0.25 * (1 + xi_n[k] * xi) * (1 + eta_n[k] * eta);
    xp += p.cp.N[k] * X[k];
    dxi += 0.25 * xi_n[k] * (1 + eta_n[k] * eta) * X[k];
    deta += 0.25 * eta_n[k] * (1 + xi_n[k] * xi) * X[k];
  }
  p.cp.master_nodes = nodes;
  p.cp.normal = dxi.cross(deta).normalized();
  p.cp.tangent = {dxi.normalized(), p.cp.normal.cross(dxi.normalized())};
  p.cp.separation = x - xp;
  p.cp.gap = p.cp.normal.dot(x - xp);
  p.distance = (x - xp).norm();
  return p;
}

std::vector<int> facet_nodes(const Mesh& m, const Facet& f) {
  std::vector<int> ids;
  for (int l : facet_local_nodes(m.type, f.local)) ids.push_back(m.element(f.element)[l]);
  return ids;
}

double facet_measure(const Mesh& m, const std::vector<int>& n) {
  if (n.size() == 2) return (point(m, n[1]) - point(m, n[0])).norm();
  return 0.5 * (point(m, n[2]) - point(m, n[0])).cross(point(m, n[3]) - point(m, n[1])).norm();
}

/// Tributary measure of every slave node: an equal share of each slave facet it belongs to.
std::map<int, double> tributary(const Mesh& m, const std::vector<Facet>& surface) {
  std::map<int, double> w;
  for (const Facet& f : surface) {
    const auto n = facet_nodes(m, f);
    const double share = facet_measure(m, n) / static_cast<double>(n.size());
    for (int id : n) w[id] += share;
  }
  return w;
}

/// The axis-aligned box of a facet's nodes.
struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  double distance(const Eigen::Vector3d& x) const { return (lo - x).cwiseMax(x - hi).cwiseMax(0.0).norm(); }
};

Box facet_box(const Mesh& m, const std::vector<int>& nodes) {
  Box b;
  for (int n : nodes) {
    b.lo = b.lo.cwiseMin(point(m, n));
    b.hi = b.hi.cwiseMax(point(m, n));
  }
  return b;
}
}  // namespace

std::vector<ContactPoint> find_contact_points(const Mesh& slave, const std::vector<Facet>& slave_surface,
                                              const Mesh& master, const std::vector<Facet>& master_surface,
                                              double search_distance, FacetCandidates candidates) {
  std::vector<std::vector<int>> facets;
  std::vector<Box> boxes;
  std::map<int, int> facets_of;  // master node → facets of the surface holding it
  for (const Facet& f : master_surface) {
    facets.push_back(facet_nodes(master, f));
    boxes.push_back(facet_box(master, facets.back()));
    for (int n : facets.back()) ++facets_of[n];
  }
  const bool all = candidates == FacetCandidates::All;
  // a closest point clamped to a facet's border counts when that border is inside the surface (its nodes shared by
  // as many facets as an interior node has): a convex master's vertex (2D) or edge (3D) region, which no facet's
  // own projection reaches — a node there would otherwise drop out of contact
  const int interior = master.dim == 2 ? 2 : 4;
  auto inside_surface = [&](const ContactPoint& cp) {
    for (size_t k = 0; k < cp.master_nodes.size(); ++k)
      if (cp.N[k] > 0 && facets_of[cp.master_nodes[k]] < interior) return false;
    return true;
  };
  std::vector<ContactPoint> points;
  const double tie = 1e-9 * search_distance;
  for (const auto& [node, weight] : tributary(slave, slave_surface)) {
    const Eigen::Vector3d x = point(slave, node);
    Projection best, clamped;
    for (size_t f = 0; f < facets.size(); ++f) {
      if (!all && boxes[f].distance(x) > search_distance) continue;  // every point of the facet is out of reach
      const std::vector<int>& nodes = facets[f];
      Projection p = master.dim == 2 ? project_on_segment(master, nodes, x) : project_on_face(master, nodes, x);
      if (p.inside && nearer(p, best, tie))
        best = std::move(p);
      else if (!p.inside && nearer(p, clamped, tie))
        clamped = std::move(p);
    }
    if (!best.inside && clamped.distance < best.distance && inside_surface(clamped.cp)) best = std::move(clamped);
    if (best.distance > search_distance) continue;
    best.cp.slave_node = node;
    best.cp.weight = weight;
    points.push_back(std::move(best.cp));
  }
  return points;
}

void facet_frame(const Mesh& master, const std::vector<int>& nodes, const std::vector<double>& N, ContactPoint& c) {
  if (nodes.size() == 2) {
    const Eigen::Vector3d t = (point(master, nodes[1]) - point(master, nodes[0])).normalized();
    c.normal = Eigen::Vector3d(t.y(), -t.x(), 0);
    c.tangent[0] = t;
    return;
  }
  // bilinear face: the isoparametric map reproduces ξ and η from the nodal values
  static const double xi_n[4] = {-1, 1, 1, -1}, eta_n[4] = {-1, -1, 1, 1};
  double xi = 0, eta = 0;
  for (int k = 0; k < 4; ++k) xi += N[k] * xi_n[k], eta += N[k] * eta_n[k];
  Eigen::Vector3d dxi = Eigen::Vector3d::Zero(), deta = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    dxi += 0.25 * xi_n[k] * (1 + eta_n[k] * eta) * point(master, nodes[k]);
    deta += 0.25 * eta_n[k] * (1 + xi_n[k] * xi) * point(master, nodes[k]);
  }
  c.normal = dxi.cross(deta).normalized();
  c.tangent = {dxi.normalized(), c.normal.cross(dxi.normalized())};
}

}  // namespace rollsim
