// Structured H8 generator for the quarter of a solid round bar: an o-grid section (square core + ring) swept along z.
#include "mesh/RoundBar.h"

#include "mesh/OGrid.h"

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

// z of node layer k: geometric element sizes from z = 0 (ratio g), summing to the length.
double layer_z(const RoundBarSpec& s, int k) {
  const double g = s.axial_grading;
  if (std::fabs(g - 1.0) < 1e-12) return s.length * k / s.n_axial;
  return s.length * (std::pow(g, k) - 1.0) / (std::pow(g, s.n_axial) - 1.0);
}

}  // namespace

double round_bar_radius(const RoundBarSpec& s, double z) {
  const double taper = s.taper_length > 0.0 ? s.taper_length : s.length;
  return s.radius * (s.neck_ratio + (1.0 - s.neck_ratio) * std::min(z / taper, 1.0));
}

Mesh make_round_bar(const RoundBarSpec& s) {
  validate(s);
  const detail::OGridQuarter sec{s.n_core, s.n_ring, s.core_fraction};
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
  const auto quads = detail::quarter_quads(sec);
  auto& all = m.element_sets["all"];
  for (int k = 0; k < s.n_axial; ++k)
    for (const detail::OGridQuad& q : quads) {
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
