// Tests of the solid round bar generator (quarter o-grid section swept along z): counts, orientation, the section's
// area against the inscribed polygon and π R² / 4, the neck's taper, the named sets and their outward normals, the
// axial grading and validation.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/RoundBar.h"

namespace rollsim::test_round_bar {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Volume of a trilinear hex by a 2x2x2 Gauss rule (exact: det J has degree <= 2 in each coordinate).
double hex_volume(const Mesh& m, int e) {
  static const int sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  double volume = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double xi[3] = {sign[q][0] * g, sign[q][1] * g, sign[q][2] * g};
    double jac[3][3] = {};  // jac[d][a] = d x_d / d xi_a
    for (int n = 0; n < 8; ++n)
      for (int a = 0; a < 3; ++a) {
        double dn = 0.125 * sign[n][a];
        for (int b = 0; b < 3; ++b)
          if (b != a) dn *= 1.0 + sign[n][b] * xi[b];
        for (int d = 0; d < 3; ++d) jac[d][a] += dn * m.nodes[m.element(e)[n]][d];
      }
    volume += jac[0][0] * (jac[1][1] * jac[2][2] - jac[1][2] * jac[2][1]) -
              jac[0][1] * (jac[1][0] * jac[2][2] - jac[1][2] * jac[2][0]) +
              jac[0][2] * (jac[1][0] * jac[2][1] - jac[1][1] * jac[2][0]);
  }
  return volume;
}

double mesh_volume(const Mesh& m) {
  double v = 0.0;
  for (int e = 0; e < m.num_elements(); ++e) v += hex_volume(m, e);
  return v;
}

// Area of the quarter of the regular polygon with 2 n segments on the quarter circle of radius r.
double quarter_polygon(double r, int n) { return n * r * r * std::sin(std::numbers::pi / (4.0 * n)); }

RoundBarSpec spec(int n_core, int n_ring, int n_axial) {
  RoundBarSpec s;
  s.radius = 6.413;
  s.length = 26.667;
  s.n_core = n_core;
  s.n_ring = n_ring;
  s.n_axial = n_axial;
  return s;
}

TEST(RoundBar, CountsNodesAndElementsOfTheOGrid) {
  const Mesh m = make_round_bar(spec(2, 3, 4));
  EXPECT_EQ(m.dim, 3);
  EXPECT_EQ(m.type, ElementType::Hex8);
  // section: (2 + 1)² core nodes + 3 rings of 2·2 + 1; five layers
  EXPECT_EQ(m.num_nodes(), (9 + 3 * 5) * 5);
  EXPECT_EQ(m.num_elements(), (4 + 2 * 2 * 3) * 4);
  EXPECT_EQ(m.element_sets.at("all").size(), static_cast<size_t>(m.num_elements()));
  EXPECT_EQ(m.node_sets.at("all").size(), static_cast<size_t>(m.num_nodes()));
}

TEST(RoundBar, EveryElementIsPositiveAcrossCoreSizesAndNecks) {
  for (double core : {0.2, 0.5, 0.7})
    for (double neck : {1.0, 0.982, 0.5}) {
      RoundBarSpec s = spec(3, 2, 5);
      s.core_fraction = core;
      s.neck_ratio = neck;
      EXPECT_NO_THROW(check_element_orientation(make_round_bar(s))) << "core " << core << ", neck " << neck;
    }
}

TEST(RoundBar, SectionIsTheInscribedPolygonAndConvergesToTheQuarterCircle) {
  double previous = 1.0;
  for (int n : {1, 2, 4, 8}) {
    const RoundBarSpec s = spec(n, 2, 3);
    const double volume = mesh_volume(make_round_bar(s));
    EXPECT_NEAR(volume, quarter_polygon(s.radius, n) * s.length, 1e-10 * volume) << n;
    const double error = 1.0 - volume / (0.25 * std::numbers::pi * s.radius * s.radius * s.length);
    EXPECT_GT(error, 0.0);
    EXPECT_LT(error, previous / 3.8) << n;  // second order in the arc's segment angle
    previous = error;
  }
  EXPECT_LT(previous, 2e-3);
}

TEST(RoundBar, NeckTapersLinearlyAndTheVolumeFollowsTheSquaredRadius) {
  RoundBarSpec s = spec(2, 2, 8);
  s.neck_ratio = 0.982;
  const Mesh m = make_round_bar(s);
  for (int node : m.node_sets.at("outer")) {
    const Vec& p = m.nodes[node];
    const double expected = s.radius * (0.982 + 0.018 * p[2] / s.length);
    EXPECT_NEAR(std::hypot(p[0], p[1]), expected, 1e-12 * s.radius) << node;
  }
  EXPECT_NEAR(round_bar_radius(s, 0.0), 0.982 * s.radius, 1e-15);
  // ∫ (r(z) / R)² dz over the length, a = 0.982, b = 0.018: L (a² + a b + b² / 3)
  const double a = 0.982, b = 0.018, scale = a * a + a * b + b * b / 3.0;
  EXPECT_NEAR(mesh_volume(m), quarter_polygon(s.radius, 2) * s.length * scale, 1e-10 * mesh_volume(m));
}

TEST(RoundBar, ShortTaperReachesTheFullRadiusWhereItEnds) {
  RoundBarSpec s = spec(2, 2, 8);
  s.neck_ratio = 0.9;
  s.taper_length = 0.25 * s.length;
  EXPECT_NEAR(round_bar_radius(s, 0.125 * s.length), 0.95 * s.radius, 1e-12);
  EXPECT_NEAR(round_bar_radius(s, 0.5 * s.length), s.radius, 1e-12);
  const Mesh m = make_round_bar(s);
  for (int node : m.node_sets.at("outer")) {
    if (m.nodes[node][2] < s.taper_length - 1e-12) continue;
    EXPECT_NEAR(std::hypot(m.nodes[node][0], m.nodes[node][1]), s.radius, 1e-12 * s.radius);
  }
}

TEST(RoundBar, NamedSetsLieOnTheirPlanesWithOutwardNormals) {
  RoundBarSpec s = spec(2, 2, 3);
  s.neck_ratio = 0.982;
  const Mesh m = make_round_bar(s);
  auto on = [&](const std::string& set, auto&& where) {
    ASSERT_TRUE(m.node_sets.count(set)) << set;
    for (int n : m.node_sets.at(set)) EXPECT_TRUE(where(m.nodes[n])) << set << " node " << n;
  };
  on("xmin", [](const Vec& p) { return std::fabs(p[0]) < 1e-12; });
  on("ymin", [](const Vec& p) { return std::fabs(p[1]) < 1e-12; });
  on("zmin", [](const Vec& p) { return std::fabs(p[2]) < 1e-12; });
  on("zmax", [&](const Vec& p) { return std::fabs(p[2] - s.length) < 1e-9; });
  // nodes per set: xmin, ymin n_core + 1 + n_ring per layer; zmin, zmax a whole section; outer 2 n_core + 1 per layer
  EXPECT_EQ(m.node_sets.at("xmin").size(), 5u * 4);
  EXPECT_EQ(m.node_sets.at("zmax").size(), 9u + 2 * 5);
  EXPECT_EQ(m.node_sets.at("outer").size(), 5u * 4);
  EXPECT_EQ(m.surfaces.at("outer").size(), 4u * 3);
  // every facet's normal (right-hand rule on its nodes) points away from its element's centroid
  for (const auto& [name, facets] : m.surfaces)
    for (const Facet& f : facets) {
      const int* conn = m.element(f.element);
      Vec c{}, fc{};
      for (int i = 0; i < 8; ++i)
        for (int d = 0; d < 3; ++d) c[d] += m.nodes[conn[i]][d] / 8;
      const auto local = facet_local_nodes(m.type, f.local);
      for (int l : local)
        for (int d = 0; d < 3; ++d) fc[d] += m.nodes[conn[l]][d] / 4;
      const Vec n = cross(sub(m.nodes[conn[local[2]]], m.nodes[conn[local[0]]]),
                          sub(m.nodes[conn[local[3]]], m.nodes[conn[local[1]]]));
      EXPECT_GT(dot(n, sub(fc, c)), 0.0) << name << " element " << f.element;
    }
}

TEST(RoundBar, AxialGradingRefinesTowardTheNeck) {
  RoundBarSpec s = spec(1, 1, 4);
  s.axial_grading = 1.5;
  const Mesh m = make_round_bar(s);
  const int per = m.num_nodes() / 5;  // nodes per section
  std::vector<double> h;
  for (int k = 0; k < 4; ++k) h.push_back(m.nodes[(k + 1) * per][2] - m.nodes[k * per][2]);
  for (int k = 1; k < 4; ++k) EXPECT_NEAR(h[k] / h[k - 1], 1.5, 1e-12);
  EXPECT_NEAR(m.nodes[4 * per][2], s.length, 1e-12);
}

TEST(RoundBar, RefusesBadSpecsNamingTheField) {
  auto refuses = [](RoundBarSpec s, const std::string& field) {
    try {
      make_round_bar(s);
      ADD_FAILURE() << field << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("RoundBarSpec." + field), std::string::npos) << e.what();
    }
  };
  RoundBarSpec s = spec(2, 2, 2);
  refuses(
      [&] {
        auto t = s;
        t.radius = 0;
        return t;
      }(),
      "radius");
  refuses(
      [&] {
        auto t = s;
        t.length = -1;
        return t;
      }(),
      "length");
  refuses(
      [&] {
        auto t = s;
        t.radius = std::nan("");
        return t;
      }(),
      "radius");
  refuses(
      [&] {
        auto t = s;
        t.n_core = 0;
        return t;
      }(),
      "n_core");
  refuses(
      [&] {
        auto t = s;
        t.n_ring = 0;
        return t;
      }(),
      "n_ring");
  refuses(
      [&] {
        auto t = s;
        t.n_axial = 0;
        return t;
      }(),
      "n_axial");
  refuses(
      [&] {
        auto t = s;
        t.core_fraction = 0.8;
        return t;
      }(),
      "core_fraction");
  refuses(
      [&] {
        auto t = s;
        t.neck_ratio = 0;
        return t;
      }(),
      "neck_ratio");
  refuses(
      [&] {
        auto t = s;
        t.neck_ratio = 1.01;
        return t;
      }(),
      "neck_ratio");
  refuses(
      [&] {
        auto t = s;
        t.taper_length = 2 * s.length;
        return t;
      }(),
      "taper_length");
  refuses(
      [&] {
        auto t = s;
        t.axial_grading = 0;
        return t;
      }(),
      "axial_grading");
}

}  // namespace
}  // namespace rollsim::test_round_bar
