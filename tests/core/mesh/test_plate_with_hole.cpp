// Tests of the quarter plate-with-hole Q4 generator: counts, orientation, area convergence, named sets,
// outward normals, grading, bandwidth and spec validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/PlateWithHole.h"

namespace rollsim::test_plate_with_hole {
namespace {

using Vec = std::array<double, 3>;

double mesh_area(const Mesh& m) {  // shoelace per element: the exact area of each bilinear Q4
  double area = 0.0;
  for (int e = 0; e < m.num_elements(); ++e) {
    const int* c = m.element(e);
    for (int k = 0; k < 4; ++k) {
      const Vec& p = m.nodes[c[k]];
      const Vec& q = m.nodes[c[(k + 1) % 4]];
      area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    }
  }
  return area;
}

Vec element_centroid(const Mesh& m, int e) {
  Vec c{};
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d) c[d] += 0.25 * m.nodes[m.element(e)[k]][d];
  return c;
}

// Outward normal (length = edge length) and midpoint of a Q4 edge.
std::array<Vec, 2> edge_normal_and_mid(const Mesh& m, const Facet& f) {
  const auto loc = facet_local_nodes(m.type, f.local);
  const Vec& a = m.nodes[m.element(f.element)[loc[0]]];
  const Vec& b = m.nodes[m.element(f.element)[loc[1]]];
  return {Vec{b[1] - a[1], a[0] - b[0], 0.0}, Vec{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.0}};
}

int bandwidth(const Mesh& m) {
  int bw = 0;
  for (int e = 0; e < m.num_elements(); ++e) {
    const auto [lo, hi] = std::minmax_element(m.element(e), m.element(e) + m.nodes_per_elem());
    bw = std::max(bw, *hi - *lo);
  }
  return bw;
}

// Every facet used by one element only is in exactly one named surface, and no facet is shared by 3 elements.
void expect_boundary_is_named(const Mesh& m) {
  std::map<std::vector<int>, int> count;
  auto key = [&](const Facet& f) {
    std::vector<int> k;
    for (int l : facet_local_nodes(m.type, f.local)) k.push_back(m.element(f.element)[l]);
    std::sort(k.begin(), k.end());
    return k;
  };
  for (int e = 0; e < m.num_elements(); ++e)
    for (int l = 0; l < 4; ++l) ++count[key({e, l})];
  std::map<std::vector<int>, int> named;
  for (const auto& [name, facets] : m.surfaces)
    for (const Facet& f : facets) ++named[key(f)];
  for (const auto& [k, c] : count) {
    EXPECT_LE(c, 2);
    EXPECT_EQ(named.count(k) ? named[k] : 0, c == 1 ? 1 : 0);
  }
  for (const auto& [k, c] : named) EXPECT_TRUE(count.count(k)) << "named facet is not an element facet";
}

// Applies `change` to the default spec and expects std::invalid_argument whose message contains `text`.
void expect_invalid(void (*change)(PlateWithHoleSpec&), const std::string& text) {
  PlateWithHoleSpec s;
  change(s);
  std::string what = "(no exception)";
  try {
    make_plate_with_hole(s);
  } catch (const std::invalid_argument& e) {
    what = e.what();
  }
  EXPECT_NE(what.find(text), std::string::npos) << "message: " << what;
}

TEST(PlateWithHole, CountsAndSets) {
  PlateWithHoleSpec s;
  s.n_around = 8;
  s.n_radial = 6;
  const Mesh m = make_plate_with_hole(s);
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.type, ElementType::Quad4);
  EXPECT_EQ(m.num_nodes(), 9 * 7);
  EXPECT_EQ(m.num_elements(), 8 * 6);
  EXPECT_EQ(m.element_sets.at("all").size(), 48u);
  EXPECT_EQ(m.node_sets.at("all").size(), 63u);
  for (const char* name : {"left", "bottom", "right", "top", "hole"}) {
    EXPECT_TRUE(m.surfaces.count(name)) << name;
    EXPECT_TRUE(m.node_sets.count(name)) << name;
  }
  EXPECT_EQ(m.node_sets.at("left").size(), 7u);
  EXPECT_EQ(m.node_sets.at("bottom").size(), 7u);
  EXPECT_EQ(m.node_sets.at("right").size(), 5u);
  EXPECT_EQ(m.node_sets.at("top").size(), 5u);
  EXPECT_EQ(m.node_sets.at("hole").size(), 9u);
  EXPECT_EQ(m.surfaces.at("hole").size(), 8u);
  EXPECT_EQ(m.surfaces.at("right").size(), 4u);
  EXPECT_EQ(m.surfaces.at("left").size(), 6u);
}

TEST(PlateWithHole, PositiveOrientationForVariousShapes) {
  const std::vector<PlateWithHoleSpec> specs = {{},
                                                {10.0, 1.0, 0.9, 8, 4, 1.0},
                                                {1.0, 5.0, 0.5, 6, 10, 1.3},
                                                {2.0, 2.0, 1.9, 2, 1, 1.0},
                                                {3.0, 1.0, 0.2, 40, 3, 2.0},
                                                {1.0, 1.0, 0.01, 16, 20, 1.25}};
  for (const auto& s : specs) {
    const Mesh m = make_plate_with_hole(s);
    EXPECT_NO_THROW(check_element_orientation(m)) << s.half_width << " " << s.half_height << " " << s.hole_radius;
    expect_boundary_is_named(m);
  }
}

TEST(PlateWithHole, AreaConvergesSecondOrder) {
  PlateWithHoleSpec s{2.0, 1.5, 0.6, 4, 2, 1.0};
  const double exact = s.half_width * s.half_height - std::numbers::pi * s.hole_radius * s.hole_radius / 4.0;
  double previous = 0.0;
  for (int level = 0; level < 5; ++level) {
    const double err = mesh_area(make_plate_with_hole(s)) - exact;
    EXPECT_GT(err, 0.0);  // the inscribed polygon misses the circular segments of the hole
    if (level > 0) {
      EXPECT_NEAR(previous / err, 4.0, 0.1) << "level " << level;
    }
    previous = err;
    s.n_around *= 2;
    s.n_radial *= 2;
  }
  EXPECT_LT(previous / exact, 1e-4);
  s.grading = 1.4;  // grading moves interior nodes only
  const double graded = mesh_area(make_plate_with_hole(s));
  s.grading = 1.0;
  EXPECT_NEAR(graded, mesh_area(make_plate_with_hole(s)), 1e-12);
}

TEST(PlateWithHole, NamedNodesLieOnTheirLoci) {
  const PlateWithHoleSpec s{3.0, 2.0, 0.75, 10, 5, 1.2};
  const Mesh m = make_plate_with_hole(s);
  const double tol = 1e-12;
  for (int n : m.node_sets.at("left")) EXPECT_NEAR(m.nodes[n][0], 0.0, tol);
  for (int n : m.node_sets.at("bottom")) EXPECT_NEAR(m.nodes[n][1], 0.0, tol);
  for (int n : m.node_sets.at("right")) EXPECT_NEAR(m.nodes[n][0], s.half_width, tol);
  for (int n : m.node_sets.at("top")) EXPECT_NEAR(m.nodes[n][1], s.half_height, tol);
  for (int n : m.node_sets.at("hole")) EXPECT_NEAR(std::hypot(m.nodes[n][0], m.nodes[n][1]), s.hole_radius, tol);
  // conversely, nodes on the loci are in the sets, and all nodes are inside the quarter plate
  auto in = [&](const char* set, int n) {
    const auto& v = m.node_sets.at(set);
    return std::find(v.begin(), v.end(), n) != v.end();
  };
  for (int n = 0; n < m.num_nodes(); ++n) {
    const auto& p = m.nodes[n];
    EXPECT_EQ(std::abs(p[0]) < tol, in("left", n));
    EXPECT_EQ(std::abs(p[1]) < tol, in("bottom", n));
    EXPECT_EQ(std::abs(p[0] - s.half_width) < tol, in("right", n));
    EXPECT_EQ(std::abs(p[1] - s.half_height) < tol, in("top", n));
    EXPECT_GE(std::hypot(p[0], p[1]), s.hole_radius - tol);
    EXPECT_LE(p[0], s.half_width + tol);
    EXPECT_LE(p[1], s.half_height + tol);
    EXPECT_EQ(p[2], 0.0);
  }
  // the corner belongs to both edges; each edge carries half of the n_around lines
  int corners = 0;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.nodes[n][0] == s.half_width && m.nodes[n][1] == s.half_height) {
      ++corners;
      EXPECT_TRUE(in("right", n) && in("top", n));
    }
  EXPECT_EQ(corners, 1);
  EXPECT_EQ(m.node_sets.at("right").size(), 6u);
  EXPECT_EQ(m.node_sets.at("top").size(), 6u);
}

TEST(PlateWithHole, FacetNormalsPointOutOfTheMaterial) {
  const PlateWithHoleSpec s{2.0, 3.0, 1.0, 12, 4, 1.1};
  const Mesh m = make_plate_with_hole(s);
  const std::map<std::string, Vec> expected = {
      {"left", {-1, 0, 0}}, {"bottom", {0, -1, 0}}, {"right", {1, 0, 0}}, {"top", {0, 1, 0}}};
  for (const auto& [name, facets] : m.surfaces)
    for (const Facet& f : facets) {
      const auto [n, mid] = edge_normal_and_mid(m, f);
      const double len = std::hypot(n[0], n[1]);
      const Vec c = element_centroid(m, f.element);
      EXPECT_GT((mid[0] - c[0]) * n[0] + (mid[1] - c[1]) * n[1], 0.0) << name;
      if (name == "hole") {
        EXPECT_GT(-(mid[0] * n[0] + mid[1] * n[1]) / (len * std::hypot(mid[0], mid[1])), 0.99);  // to the centre
      } else {
        EXPECT_NEAR(n[0] / len, expected.at(name)[0], 1e-12) << name;
        EXPECT_NEAR(n[1] / len, expected.at(name)[1], 1e-12) << name;
      }
    }
}

TEST(PlateWithHole, GradingGrowsRadialSizesGeometrically) {
  const PlateWithHoleSpec s{4.0, 4.0, 1.0, 4, 5, 1.5};
  const Mesh m = make_plate_with_hole(s);
  std::vector<double> x;
  for (int n : m.node_sets.at("bottom")) x.push_back(m.nodes[n][0]);
  std::sort(x.begin(), x.end());
  ASSERT_EQ(x.size(), 6u);
  EXPECT_DOUBLE_EQ(x.front(), 1.0);
  EXPECT_DOUBLE_EQ(x.back(), 4.0);
  for (size_t k = 1; k + 1 < x.size(); ++k) EXPECT_NEAR((x[k + 1] - x[k]) / (x[k] - x[k - 1]), 1.5, 1e-12);
}

TEST(PlateWithHole, NumberingKeepsBandwidthSmall) {
  EXPECT_LE(bandwidth(make_plate_with_hole({1.0, 1.0, 0.3, 40, 4, 1.0})), 4 + 2);  // radial fastest
  EXPECT_LE(bandwidth(make_plate_with_hole({1.0, 1.0, 0.3, 4, 30, 1.0})), 4 + 2);  // around fastest
  EXPECT_LE(bandwidth(make_plate_with_hole({1.0, 1.0, 0.3, 6, 6, 1.0})), 6 + 2);
}

TEST(PlateWithHole, InvalidSpecsThrowNamingTheField) {
  using S = PlateWithHoleSpec;
  expect_invalid([](S& s) { s.hole_radius = 1.0; }, "hole radius must be smaller than the plate half-width");
  expect_invalid([](S& s) { s.half_height = 0.2; }, "hole radius must be smaller than the plate half-height");
  expect_invalid([](S& s) { s.hole_radius = 0.0; }, "hole_radius");
  expect_invalid([](S& s) { s.half_width = -1.0; }, "half_width");
  expect_invalid([](S& s) { s.half_height = std::nan(""); }, "half_height");
  expect_invalid([](S& s) { s.n_around = 7; }, "n_around");
  expect_invalid([](S& s) { s.n_around = 0; }, "n_around");
  expect_invalid([](S& s) { s.n_radial = 0; }, "n_radial");
  expect_invalid([](S& s) { s.grading = 0.9; }, "grading");
  expect_invalid([](S& s) { s.grading = 1e300; }, "grading");
}

}  // namespace
}  // namespace rollsim::test_plate_with_hole
