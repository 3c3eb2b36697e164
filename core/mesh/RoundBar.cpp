// Structured H8 generator for the quarter of a solid round bar: an o-grid section (square core + ring) swept along z.
#include "mesh/RoundBar.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollsim {

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("RoundBarSpec." + what);
}

void validate(const RoundBarSpec& s) {
  require(std::isfinite(s.radius) && s.radius > 0.0, "radius must be positive");
  require(std::isfinite(s.length) && s.length > 0.0, "length must be positive");
  require(s.n_core >= 1, "n_core must be at least 1");
  require(s.n_ring >= 1, "n_ring must be at least 1");
  require(s.n_axial >= 1, "n_axial must be at least 1");
  require(s.core_fraction >= 0.2 && s.core_fraction <= 0.7, "core_fraction must lie in [0.2, 0.7]");
  require(s.neck_ratio > 0.0 && s.neck_ratio <= 1.0, "neck_ratio must lie in (0, 1]");
  require(std::isfinite(s.taper_length) && s.taper_length >= 0.0 && s.taper_length <= s.length,
          "taper_length must lie in [0, length] (0: the whole length)");
  require(std::isfinite(s.axial_grading) && s.axial_grading > 0.0, "axial_grading must be positive");
}

// The quarter section of unit radius: (n_core + 1)² core nodes (i fastest), then n_ring rings of 2 n_core + 1 nodes
// from the positive x axis (s = 0) round to the positive y axis (s = 2 n_core); ring 0 is the core's outer edge.
struct Section {
  int n, m;  // n_core, n_ring
  double a;  // half-side of the core (unit radius)
  int core(int i, int j) const { return j * (n + 1) + i; }
  int ring(int k, int s) const {  // k = 0 … m layers outward
    if (k == 0) return s <= n ? core(n, s) : core(2 * n - s, n);
    return (n + 1) * (n + 1) + (k - 1) * (2 * n + 1) + s;
  }
  int nodes() const { return (n + 1) * (n + 1) + m * (2 * n + 1); }

  std::array<double, 2> inner(int s) const {  // the core's outer edge
    return s <= n ? std::array<double, 2>{a, a * s / n} : std::array<double, 2>{a * (2 * n - s) / n, a};
  }
  std::array<double, 2> position(int local) const {
    if (local < (n + 1) * (n + 1)) return {a * (local % (n + 1)) / n, a * (local / (n + 1)) / n};
    const int r = local - (n + 1) * (n + 1), k = r / (2 * n + 1) + 1, s = r % (2 * n + 1);
    const double t = static_cast<double>(k) / m, angle = 0.25 * std::numbers::pi * s / n;
    const auto p = inner(s);
    return {(1 - t) * p[0] + t * std::cos(angle), (1 - t) * p[1] + t * std::sin(angle)};
  }
};

// z of node layer k: geometric element sizes from z = 0 (ratio g), summing to the length.
double layer_z(const RoundBarSpec& s, int k) {
  const double g = s.axial_grading;
  if (std::fabs(g - 1.0) < 1e-12) return s.length * k / s.n_axial;
  return s.length * (std::pow(g, k) - 1.0) / (std::pow(g, s.n_axial) - 1.0);
}

// One element of the section with its bottom face counter-clockwise seen from +z, swept from layer k to k + 1;
// the faces it contributes to the symmetry planes and the round surface.
struct Quad {
  std::array<int, 4> v;
  int ymin_face = -1, xmin_face = -1, outer_face = -1;  // local H8 facet (Mesh.h), -1: none
};

std::vector<Quad> section_quads(const Section& sec) {
  std::vector<Quad> q;
  const int n = sec.n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      q.push_back({{sec.core(i, j), sec.core(i + 1, j), sec.core(i + 1, j + 1), sec.core(i, j + 1)},
                   j == 0 ? 2 : -1,
                   i == 0 ? 5 : -1,
                   -1});
  for (int k = 0; k < sec.m; ++k)  // outward (k) then round (s): e_r × e_θ = +z
    for (int s = 0; s < 2 * n; ++s)
      q.push_back({{sec.ring(k, s), sec.ring(k + 1, s), sec.ring(k + 1, s + 1), sec.ring(k, s + 1)},
                   s == 0 ? 2 : -1,
                   s == 2 * n - 1 ? 4 : -1,
                   k == sec.m - 1 ? 3 : -1});
  return q;
}
}  // namespace

double round_bar_radius(const RoundBarSpec& s, double z) {
  const double taper = s.taper_length > 0.0 ? s.taper_length : s.length;
  return s.radius * (s.neck_ratio + (1.0 - s.neck_ratio) * std::min(z / taper, 1.0));
}

Mesh make_round_bar(const RoundBarSpec& s) {
  validate(s);
  const Section sec{s.n_core, s.n_ring, s.core_fraction};
  const int per = sec.nodes();
  Mesh m;
  m.dim = 3;
  m.type = ElementType::Hex8;
  m.nodes.resize(static_cast<size_t>(per) * (s.n_axial + 1));
  for (int k = 0; k <= s.n_axial; ++k) {
    const double z = layer_z(s, k), r = round_bar_radius(s, z);
    for (int l = 0; l < per; ++l) {
      const auto p = sec.position(l);
      m.nodes[static_cast<size_t>(k) * per + l] = {r * p[0], r * p[1], z};
    }
  }
  const auto quads = section_quads(sec);
  auto& all = m.element_sets["all"];
  for (int k = 0; k < s.n_axial; ++k)
    for (const Quad& q : quads) {
      const int e = m.num_elements();
      for (int layer : {k, k + 1})
        for (int v : q.v) m.connectivity.push_back(layer * per + v);
      all.push_back(e);
      if (k == 0) m.surfaces["zmin"].push_back({e, 0});
      if (k == s.n_axial - 1) m.surfaces["zmax"].push_back({e, 1});
      if (q.ymin_face >= 0) m.surfaces["ymin"].push_back({e, q.ymin_face});
      if (q.xmin_face >= 0) m.surfaces["xmin"].push_back({e, q.xmin_face});
      if (q.outer_face >= 0) m.surfaces["outer"].push_back({e, q.outer_face});
    }
  add_derived_node_sets(m);
  return m;
}

}  // namespace rollsim
