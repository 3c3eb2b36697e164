// Structured Q4 generator for the quarter model of a rectangular plate with a central circular hole.
#include "mesh/PlateWithHole.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rollsim {

namespace {
using Point = std::array<double, 2>;

void require(bool ok, const char* message) {
  if (!ok) throw std::invalid_argument(std::string("PlateWithHoleSpec.") + message);
}

void validate(const PlateWithHoleSpec& s) {
  require(std::isfinite(s.half_width) && s.half_width > 0.0, "half_width must be positive");
  require(std::isfinite(s.half_height) && s.half_height > 0.0, "half_height must be positive");
  require(std::isfinite(s.hole_radius) && s.hole_radius > 0.0, "hole_radius must be positive");
  require(s.hole_radius < s.half_width, "hole_radius: hole radius must be smaller than the plate half-width");
  require(s.hole_radius < s.half_height, "hole_radius: hole radius must be smaller than the plate half-height");
  require(s.n_around >= 2 && s.n_around % 2 == 0, "n_around must be even and at least 2");
  require(s.n_radial >= 1, "n_radial must be at least 1");
  require(std::isfinite(s.grading) && s.grading >= 1.0, "grading must be at least 1");
  require(std::isfinite(std::pow(s.grading, s.n_radial)), "grading is too large for n_radial");
}

// Fraction of the way from the hole to the outer edge of radial node j; element sizes grow by `grading`.
double radial_fraction(int j, int n, double grading) {
  if (j >= n) return 1.0;
  if (grading - 1.0 < 1e-12) return static_cast<double>(j) / n;
  return (std::pow(grading, j) - 1.0) / (std::pow(grading, n) - 1.0);
}

// Point of the hole (t = 0) or of the outer boundary (t = 1) on radial line i.
Point hole_point(const PlateWithHoleSpec& s, int i) {
  if (i == 0) return {s.hole_radius, 0.0};
  if (i == s.n_around) return {0.0, s.hole_radius};
  const double theta = 0.5 * std::numbers::pi * i / s.n_around;
  return {s.hole_radius * std::cos(theta), s.hole_radius * std::sin(theta)};
}

Point edge_point(const PlateWithHoleSpec& s, int i) {
  const int half = s.n_around / 2;
  if (i <= half) return {s.half_width, s.half_height * i / half};
  return {s.half_width * (s.n_around - i) / half, s.half_height};
}

// Node / element numbering of the (around i, radial j) grid: the direction with fewer nodes varies fastest.
struct Numbering {
  int n_around, n_radial;
  bool radial_fast;
  int node(int i, int j) const { return radial_fast ? j + i * (n_radial + 1) : i + j * (n_around + 1); }
  std::array<int, 2> element(int e) const {
    if (radial_fast) return {e / n_radial, e % n_radial};
    return {e % n_around, e / n_around};
  }
};

void add_nodes(Mesh& m, const PlateWithHoleSpec& s, const Numbering& num) {
  m.nodes.resize(static_cast<size_t>(s.n_around + 1) * (s.n_radial + 1));
  for (int i = 0; i <= s.n_around; ++i) {
    const Point p = hole_point(s, i), q = edge_point(s, i);
    for (int j = 0; j <= s.n_radial; ++j) {
      const double t = radial_fraction(j, s.n_radial, s.grading);
      m.nodes[num.node(i, j)] = {(1.0 - t) * p[0] + t * q[0], (1.0 - t) * p[1] + t * q[1], 0.0};
    }
  }
}

void add_elements(Mesh& m, const PlateWithHoleSpec& s, const Numbering& num) {
  auto& all = m.element_sets["all"];
  for (int e = 0; e < s.n_around * s.n_radial; ++e) {
    const auto [i, j] = num.element(e);
    // radial edge first, then along the hole: counter-clockwise
    for (int v : {num.node(i, j), num.node(i, j + 1), num.node(i + 1, j + 1), num.node(i + 1, j)})
      m.connectivity.push_back(v);
    if (j == 0) m.surfaces["hole"].push_back({e, 3});
    if (j == s.n_radial - 1) m.surfaces[i < s.n_around / 2 ? "right" : "top"].push_back({e, 1});
    if (i == 0) m.surfaces["bottom"].push_back({e, 0});
    if (i == s.n_around - 1) m.surfaces["left"].push_back({e, 2});
    all.push_back(e);
  }
}
}  // namespace

Mesh make_plate_with_hole(const PlateWithHoleSpec& s) {
  validate(s);
  const Numbering num{s.n_around, s.n_radial, s.n_radial <= s.n_around};
  Mesh m;
  m.dim = 2;
  m.type = ElementType::Quad4;
  add_nodes(m, s, num);
  add_elements(m, s, num);
  add_derived_node_sets(m);
  return m;
}

}  // namespace rollsim
