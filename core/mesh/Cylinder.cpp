// Structured H8 generator for a hollow cylinder (or cylindrical sector) with its axis parallel to y.
#include "mesh/Cylinder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "mesh/Annulus.h"

namespace rollsim {

namespace {
void validate(const CylinderSpec& s) {
  if (!std::isfinite(s.cx) || !std::isfinite(s.cz)) throw std::invalid_argument("CylinderSpec.cx/cz must be finite");
  if (!std::isfinite(s.y0)) throw std::invalid_argument("CylinderSpec.y0 must be finite");
  if (!std::isfinite(s.length) || !(s.length > 0.0))
    throw std::invalid_argument("CylinderSpec.length must be positive");
  if (s.n_axial < 1) throw std::invalid_argument("CylinderSpec.n_axial must be at least 1");
  detail::validate_ring("CylinderSpec", s.inner_radius, s.outer_radius, s.n_radial, s.n_around, s.theta0, s.theta1);
  if (!(s.outer_radius + s.outer_profile.lowest() > s.inner_radius))
    throw std::invalid_argument("CylinderSpec.outer_profile takes the outer radius down to the inner one");
}

// Numbering of the (around i, radial j, axial k) grid: axes sorted by node count, fewest nodes fastest;
// elements use the same axis order.
struct Numbering {
  const detail::RingLayout& ring;
  std::array<int, 3> elems;  // elements along around, radial, axial
  std::array<int, 3> nodes;  // node positions along around, radial, axial
  std::array<int, 3> order;  // axes, fastest first
  std::array<int, 3> node_stride{}, elem_stride{};

  Numbering(const detail::RingLayout& r, int n_radial, int n_axial)
      : ring(r), elems{r.n_around, n_radial, n_axial}, nodes{r.positions(), n_radial + 1, n_axial + 1}, order{0, 1, 2} {
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return nodes[a] < nodes[b]; });
    int ns = 1, es = 1;
    for (int a : order) {
      node_stride[a] = ns;
      elem_stride[a] = es;
      ns *= nodes[a];
      es *= elems[a];
    }
  }
  int node(int i, int j, int k) const {
    const int na = nodes[0];
    return ring.rank(i % na, na) * node_stride[0] + j * node_stride[1] + k * node_stride[2];
  }
  std::array<int, 3> element(int e) const {
    std::array<int, 3> idx{};
    for (int a : order) idx[a] = (e / elem_stride[a]) % elems[a];
    idx[0] = ring.position(idx[0], elems[0]);
    return idx;
  }
};

void add_nodes(Mesh& m, const CylinderSpec& s, const detail::RingLayout& ring, const Numbering& num) {
  m.nodes.resize(static_cast<size_t>(num.nodes[0]) * num.nodes[1] * num.nodes[2]);
  for (int i = 0; i < ring.positions(); ++i) {
    const auto d = ring.direction(i);
    for (int j = 0; j <= s.n_radial; ++j) {
      const double t = static_cast<double>(j) / s.n_radial;
      for (int k = 0; k <= s.n_axial; ++k) {
        const double y = s.y0 + s.length * (static_cast<double>(k) / s.n_axial);
        const double r = (1.0 - t) * s.inner_radius + t * (s.outer_radius + s.outer_profile.at(y));
        m.nodes[num.node(i, j, k)] = {s.cx + r * d[0], y, s.cz + r * d[1]};
      }
    }
  }
}

void add_facets(Mesh& m, const CylinderSpec& s, bool closed, int e, int i, int j, int k) {
  if (k == 0) m.surfaces["ymin"].push_back({e, 0});
  if (k == s.n_axial - 1) m.surfaces["ymax"].push_back({e, 1});
  if (j == 0) m.surfaces["inner"].push_back({e, 2});
  if (!closed && i == s.n_around - 1) m.surfaces["end"].push_back({e, 3});
  if (j == s.n_radial - 1) m.surfaces["outer"].push_back({e, 4});
  if (!closed && i == 0) m.surfaces["start"].push_back({e, 5});
}

void add_elements(Mesh& m, const CylinderSpec& s, const detail::RingLayout& ring, const Numbering& num) {
  auto& all = m.element_sets["all"];
  const int total = s.n_around * s.n_radial * s.n_axial;
  for (int e = 0; e < total; ++e) {
    const auto [i, j, k] = num.element(e);
    // bottom face: along the ring, then outward; (e_theta x e_r) = +y points to the top face at k + 1
    for (int kk : {k, k + 1})
      for (int v : {num.node(i, j, kk), num.node(i + 1, j, kk), num.node(i + 1, j + 1, kk), num.node(i, j + 1, kk)})
        m.connectivity.push_back(v);
    add_facets(m, s, ring.closed, e, i, j, k);
    all.push_back(e);
  }
}
}  // namespace

Mesh make_cylinder(const CylinderSpec& s) {
  validate(s);
  const detail::RingLayout ring(s.theta0, s.theta1, s.n_around);
  const Numbering num(ring, s.n_radial, s.n_axial);
  Mesh m;
  m.dim = 3;
  m.type = ElementType::Hex8;
  add_nodes(m, s, ring, num);
  add_elements(m, s, ring, num);
  add_derived_node_sets(m);
  return m;
}

}  // namespace rollsim
