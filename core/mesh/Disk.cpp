#include "mesh/Disk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mesh/OGrid.h"

namespace rollsim {

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("DiskSpec." + what);
}

bool quarter_turn(double degrees) { return std::fabs(degrees / 90.0 - std::round(degrees / 90.0)) < 1e-12; }

void validate(const DiskSpec& s) {
  require(s.dim == 2 || s.dim == 3, "dim must be 2 or 3");
  require(std::isfinite(s.radius) && s.radius > 0.0, "radius must be positive");
  require(s.n_core >= 1, "n_core must be at least 1");
  require(s.n_ring >= 1, "n_ring must be at least 1");
  require(s.core_fraction >= 0.2 && s.core_fraction <= 0.7, "core_fraction must lie in [0.2, 0.7]");
  require(quarter_turn(s.theta0) && quarter_turn(s.theta1), "theta0 and theta1 must be multiples of 90 degrees");
  require(s.theta1 > s.theta0 && s.theta1 - s.theta0 <= 360.0, "theta1 must exceed theta0 by at most 360 degrees");
  if (s.dim == 3) {
    require(std::isfinite(s.length) && s.length > 0.0, "length must be positive");
    require(s.n_axial >= 1, "n_axial must be at least 1");
  }
}

/// The section of unit radius over the span: its distinct nodes (the quarters' shared edges merged) and, per quarter,
/// the section node of each of the quarter's local nodes.
struct Section {
  std::vector<std::array<double, 2>> nodes;
  std::vector<std::vector<int>> quarter_nodes;
};

Section section(const detail::OGridQuarter& quarter, int first, int count) {
  Section s;
  std::map<std::pair<long long, long long>, int> at;  // rounded position -> node (turns by 90° are exact but cos 90°)
  for (int q = 0; q < count; ++q) {
    const int turn = ((first + q) % 4 + 4) % 4;
    std::vector<int>& ids = s.quarter_nodes.emplace_back();
    for (int l = 0; l < quarter.nodes(); ++l) {
      auto p = quarter.position(l);
      for (int t = 0; t < turn; ++t) p = {-p[1], p[0]};
      const auto key = std::make_pair(std::llround(p[0] * 1e9), std::llround(p[1] * 1e9));
      const auto [it, added] = at.emplace(key, static_cast<int>(s.nodes.size()));
      if (added) s.nodes.push_back(p);
      ids.push_back(it->second);
    }
  }
  return s;
}
}  // namespace

Mesh make_disk(const DiskSpec& spec) {
  validate(spec);
  const detail::OGridQuarter quarter{spec.n_core, spec.n_ring, spec.core_fraction};
  const int first = static_cast<int>(std::lround(spec.theta0 / 90.0));
  const int count = static_cast<int>(std::lround((spec.theta1 - spec.theta0) / 90.0));
  const bool closed = count == 4;
  const Section sec = section(quarter, first, count);
  const int per = static_cast<int>(sec.nodes.size()), layers = spec.dim == 3 ? spec.n_axial + 1 : 1;
  Mesh m;
  m.dim = spec.dim;
  m.type = spec.dim == 2 ? ElementType::Quad4 : ElementType::Hex8;
  for (int k = 0; k < layers; ++k)
    for (const auto& p : sec.nodes) {
      const double a = spec.c0 + spec.radius * p[0], b = spec.c1 + spec.radius * p[1];
      m.nodes.push_back(spec.dim == 2 ? std::array<double, 3>{a, b, 0.0}
                                      : std::array<double, 3>{a, spec.y0 + spec.length * k / spec.n_axial, b});
    }
  // 2D: a quad's H8 side face f (OGrid.h) is its edge f − 2. 3D: the section lies in x-z, where e_x × e_z = −e_y, so
  // the element's bottom face is the layer at larger y (face 0: ymax side, face 1: ymin side) to be positive.
  const int side = spec.dim == 2 ? -2 : 0;
  const auto quads = detail::quarter_quads(quarter);
  auto& all = m.element_sets["all"];
  for (int k = 0; k + 1 < std::max(layers, 2); ++k)  // 2D: one pass (k = 0); 3D: each layer of elements
    for (int q = 0; q < count; ++q)
      for (const detail::OGridQuad& quad : quads) {
        const int e = m.num_elements();
        const int bottom = spec.dim == 2 ? 0 : k + 1;
        for (int v : quad.v) m.connectivity.push_back(bottom * per + sec.quarter_nodes[q][v]);
        if (spec.dim == 3)
          for (int v : quad.v) m.connectivity.push_back(k * per + sec.quarter_nodes[q][v]);
        all.push_back(e);
        if (quad.outer_face >= 0) m.surfaces["outer"].push_back({e, quad.outer_face + side});
        if (!closed && q == 0 && quad.ymin_face >= 0) m.surfaces["start"].push_back({e, quad.ymin_face + side});
        if (!closed && q == count - 1 && quad.xmin_face >= 0) m.surfaces["end"].push_back({e, quad.xmin_face + side});
        if (spec.dim == 3 && k == 0) m.surfaces["ymin"].push_back({e, 1});
        if (spec.dim == 3 && k == spec.n_axial - 1) m.surfaces["ymax"].push_back({e, 0});
      }
  for (int k = 0; k < layers; ++k) m.node_sets["center"].push_back(k * per + sec.quarter_nodes[0][quarter.core(0, 0)]);
  add_derived_node_sets(m);
  return m;
}

}  // namespace rollsim
