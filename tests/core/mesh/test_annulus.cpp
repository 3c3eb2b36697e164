// Tests of the Q4 annulus / annular-sector generator: counts, closed-ring topology, orientation, area
// convergence, named sets, outward normals, bandwidth and spec validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/Annulus.h"

namespace rollsim::test_annulus {
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

// Smallest distance between two distinct nodes, and whether every node is used by an element.
double min_node_distance(const Mesh& m) {
  double d = INFINITY;
  for (int a = 0; a < m.num_nodes(); ++a)
    for (int b = a + 1; b < m.num_nodes(); ++b)
      d = std::min(d, std::hypot(m.nodes[a][0] - m.nodes[b][0], m.nodes[a][1] - m.nodes[b][1]));
  return d;
}

bool all_nodes_used(const Mesh& m) {
  std::vector<bool> used(m.nodes.size(), false);
  for (int v : m.connectivity) used[v] = true;
  return std::all_of(used.begin(), used.end(), [](bool u) { return u; });
}

double exact_area(const AnnulusSpec& s) {
  return std::numbers::pi * (s.outer_radius * s.outer_radius - s.inner_radius * s.inner_radius) *
         (s.theta1 - s.theta0) / 360.0;
}

void expect_invalid(void (*change)(AnnulusSpec&), const std::string& text) {
  AnnulusSpec s;
  change(s);
  std::string what = "(no exception)";
  try {
    make_annulus(s);
  } catch (const std::invalid_argument& e) {
    what = e.what();
  }
  EXPECT_NE(what.find(text), std::string::npos) << "message: " << what;
}

TEST(Annulus, FullRingSharesTheSeamNodes) {
  for (auto [na, nr] : {std::array<int, 2>{16, 3}, {3, 1}, {4, 12}}) {
    AnnulusSpec s;
    s.n_around = na;
    s.n_radial = nr;
    s.cx = 2.0;
    s.cy = -1.0;
    const Mesh m = make_annulus(s);
    EXPECT_EQ(m.num_nodes(), na * (nr + 1));
    EXPECT_EQ(m.num_elements(), na * nr);
    EXPECT_GT(min_node_distance(m), 1e-3);
    EXPECT_TRUE(all_nodes_used(m));
    EXPECT_EQ(m.surfaces.count("start") + m.surfaces.count("end") + m.node_sets.count("start"), 0u);
    EXPECT_EQ(m.surfaces.at("inner").size(), static_cast<size_t>(na));
    EXPECT_EQ(m.node_sets.at("outer").size(), static_cast<size_t>(na));
    EXPECT_EQ(m.node_sets.at("all").size(), m.nodes.size());
    EXPECT_EQ(m.element_sets.at("all").size(), static_cast<size_t>(na * nr));
    expect_boundary_is_named(m);  // no open seam: the only boundary is inner + outer
    EXPECT_NO_THROW(check_element_orientation(m));
  }
}

TEST(Annulus, PartialSpanHasRadialEdges) {
  const AnnulusSpec s{0.0, 0.0, 1.0, 2.0, 3, 6, 0.0, 90.0};
  const Mesh m = make_annulus(s);
  EXPECT_EQ(m.num_nodes(), 7 * 4);
  EXPECT_EQ(m.num_elements(), 18);
  EXPECT_EQ(m.surfaces.at("start").size(), 3u);
  EXPECT_EQ(m.surfaces.at("end").size(), 3u);
  EXPECT_EQ(m.node_sets.at("start").size(), 4u);
  EXPECT_EQ(m.node_sets.at("inner").size(), 7u);
  for (int n : m.node_sets.at("start")) EXPECT_EQ(m.nodes[n][1], 0.0);  // exact on the symmetry lines
  for (int n : m.node_sets.at("end")) EXPECT_EQ(m.nodes[n][0], 0.0);
  expect_boundary_is_named(m);
}

TEST(Annulus, PositiveOrientationForVariousSpans) {
  const std::vector<AnnulusSpec> specs = {{},
                                          {1.0, 2.0, 1e-3, 0.3, 6, 40, 0.0, 360.0},
                                          {0.0, 0.0, 1.0, 1.5, 2, 3, 10.0, 350.0},
                                          {0.0, 0.0, 0.2, 1.0, 4, 8, -45.0, 45.0},
                                          {5.0, 5.0, 0.9, 1.0, 1, 3, -180.0, 180.0},
                                          {0.0, 0.0, 0.5, 1.0, 3, 1, 200.0, 300.0}};
  for (const auto& s : specs) {
    const Mesh m = make_annulus(s);
    EXPECT_NO_THROW(check_element_orientation(m)) << s.theta0 << ".." << s.theta1;
    expect_boundary_is_named(m);
  }
}

TEST(Annulus, AreaConvergesSecondOrder) {
  for (auto [t0, t1] : {std::array<double, 2>{0.0, 360.0}, {0.0, 90.0}, {-30.0, 100.0}}) {
    AnnulusSpec s{0.5, -0.5, 0.3, 1.0, 2, 8, t0, t1};
    double previous = 0.0;
    for (int level = 0; level < 5; ++level) {
      const double area = mesh_area(make_annulus(s));
      const double delta = (t1 - t0) / s.n_around * std::numbers::pi / 180.0;  // the exact polygon area:
      const double polygon =
          0.5 * s.n_around * std::sin(delta) * (s.outer_radius * s.outer_radius - s.inner_radius * s.inner_radius);
      EXPECT_NEAR(area, polygon, 1e-13);
      const double err = exact_area(s) - area;
      EXPECT_GT(err, 0.0);  // outer polygon inscribed: too little area
      if (level > 0) {
        EXPECT_NEAR(previous / err, 4.0, 0.1) << t0 << ".." << t1 << " level " << level;
      }
      previous = err;
      s.n_around *= 2;
      s.n_radial *= 2;
    }
    EXPECT_LT(previous / exact_area(s), 1e-3);
  }
}

TEST(Annulus, NamedNodesLieOnTheirLoci) {
  const AnnulusSpec s{1.5, -2.0, 0.4, 1.1, 3, 10, 30.0, 150.0};
  const Mesh m = make_annulus(s);
  auto radius = [&](int n) { return std::hypot(m.nodes[n][0] - s.cx, m.nodes[n][1] - s.cy); };
  auto angle = [&](int n) { return std::atan2(m.nodes[n][1] - s.cy, m.nodes[n][0] - s.cx) * 180.0 / std::numbers::pi; };
  for (int n : m.node_sets.at("inner")) EXPECT_NEAR(radius(n), s.inner_radius, 1e-12);
  for (int n : m.node_sets.at("outer")) EXPECT_NEAR(radius(n), s.outer_radius, 1e-12);
  for (int n : m.node_sets.at("start")) EXPECT_NEAR(angle(n), s.theta0, 1e-10);
  for (int n : m.node_sets.at("end")) EXPECT_NEAR(angle(n), s.theta1, 1e-10);
  for (int n = 0; n < m.num_nodes(); ++n) {
    EXPECT_GE(radius(n), s.inner_radius - 1e-12);
    EXPECT_LE(radius(n), s.outer_radius + 1e-12);
    EXPECT_GE(angle(n), s.theta0 - 1e-10);
    EXPECT_LE(angle(n), s.theta1 + 1e-10);
  }
}

TEST(Annulus, FacetNormalsPointOutOfTheMaterial) {
  for (const AnnulusSpec& s : {AnnulusSpec{0.7, 0.2, 0.5, 1.0, 3, 12, 20.0, 250.0}, AnnulusSpec{}}) {
    const Mesh m = make_annulus(s);
    const double t0 = s.theta0 * std::numbers::pi / 180.0, t1 = s.theta1 * std::numbers::pi / 180.0;
    for (const auto& [name, facets] : m.surfaces)
      for (const Facet& f : facets) {
        const auto [n, mid] = edge_normal_and_mid(m, f);
        const double len = std::hypot(n[0], n[1]);
        const double rx = mid[0] - s.cx, ry = mid[1] - s.cy, r = std::hypot(rx, ry);
        const Vec c = element_centroid(m, f.element);
        EXPECT_GT((mid[0] - c[0]) * n[0] + (mid[1] - c[1]) * n[1], 0.0) << name;
        const double radial = (rx * n[0] + ry * n[1]) / (r * len);
        if (name == "inner") {
          EXPECT_GT(-radial, 0.99);  // towards the centre
        }
        if (name == "outer") {
          EXPECT_GT(radial, 0.99);
        }
        if (name == "start") {
          EXPECT_NEAR(n[0] * std::sin(t0) - n[1] * std::cos(t0), len, 1e-12);  // -e_theta
        }
        if (name == "end") {
          EXPECT_NEAR(-n[0] * std::sin(t1) + n[1] * std::cos(t1), len, 1e-12);  // +e_theta
        }
      }
  }
}

TEST(Annulus, ClosedRingNumberingKeepsBandwidthSmall) {
  // without folding, the seam element would couple the first and the last column of nodes
  EXPECT_LE(bandwidth(make_annulus({0.0, 0.0, 0.5, 1.0, 4, 64, 0.0, 360.0})), 2 * 5 + 1);
  EXPECT_LE(bandwidth(make_annulus({0.0, 0.0, 0.5, 1.0, 30, 6, 0.0, 360.0})), 6 + 2);
  EXPECT_LE(bandwidth(make_annulus({0.0, 0.0, 0.5, 1.0, 4, 64, 0.0, 180.0})), 5 + 1);
  EXPECT_LE(bandwidth(make_annulus({0.0, 0.0, 0.5, 1.0, 30, 6, 0.0, 180.0})), 7 + 1);
}

TEST(Annulus, InvalidSpecsThrowNamingTheField) {
  using S = AnnulusSpec;
  expect_invalid([](S& s) { s.inner_radius = 0.0; }, "inner_radius");
  expect_invalid([](S& s) { s.outer_radius = 0.5; }, "outer_radius must be larger than inner_radius");
  expect_invalid([](S& s) { s.n_radial = 0; }, "n_radial");
  expect_invalid([](S& s) { s.n_around = 0; }, "n_around");
  expect_invalid([](S& s) { s.n_around = 2; }, "n_around");  // two 180-degree elements would be flat
  expect_invalid([](S& s) { s.theta1 = s.theta0; }, "theta1");
  expect_invalid([](S& s) { s.theta1 = 400.0; }, "360");
  expect_invalid([](S& s) { s.theta0 = std::nan(""); }, "theta0");
  expect_invalid([](S& s) { s.cy = INFINITY; }, "cx/cy");
}

}  // namespace
}  // namespace rollsim::test_annulus
