#pragma once
// The o-grid of a solid round section, shared by the round bar and the disk generators: the quarter x >= 0, y >= 0 of
// the unit circle as a square core and a ring around it, and its quadrilaterals with the faces they give to the
// straight edges and the round surface.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace rollsim::detail {

// The quarter section of unit radius: (n_core + 1)² core nodes (i fastest), then n_ring rings of 2 n_core + 1 nodes
// from the positive x axis (s = 0) round to the positive y axis (s = 2 n_core); ring 0 is the core's outer edge.
struct OGridQuarter {
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

// One element of the section with its bottom face counter-clockwise seen from +z, swept from layer k to k + 1;
// the faces it contributes to the symmetry planes and the round surface.
struct OGridQuad {
  std::array<int, 4> v;
  int ymin_face = -1, xmin_face = -1, outer_face = -1;  // local H8 facet (Mesh.h), -1: none
};

/// The quarter's quadrilaterals, core first (row by row), then the ring (outward, then round).
std::vector<OGridQuad> quarter_quads(const OGridQuarter& quarter);

}  // namespace rollsim::detail
