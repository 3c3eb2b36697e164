// Tests of the H8 hollow-cylinder generator (axis along y): counts, closed-ring topology, orientation, volume
// convergence, named sets, outward normals, consistency with the annulus section, bandwidth and validation.
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
#include "mesh/Cylinder.h"

namespace rollsim::test_cylinder {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

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

Vec centroid(const Mesh& m, const int* conn, const std::vector<int>& local) {
  Vec c{};
  for (int l : local)
    for (int d = 0; d < 3; ++d) c[d] += m.nodes[conn[l]][d] / static_cast<double>(local.size());
  return c;
}

// Outward area-weighted normal (right-hand rule on the facet's node order) and centroid of an H8 face.
std::array<Vec, 2> face_normal_and_centroid(const Mesh& m, const Facet& f) {
  const auto loc = facet_local_nodes(m.type, f.local);
  const int* c = m.element(f.element);
  auto p = [&](int k) { return m.nodes[c[loc[k]]]; };
  return {cross(sub(p(2), p(0)), sub(p(3), p(1))), centroid(m, c, loc)};
}

int bandwidth(const Mesh& m) {
  int bw = 0;
  for (int e = 0; e < m.num_elements(); ++e) {
    const auto [lo, hi] = std::minmax_element(m.element(e), m.element(e) + m.nodes_per_elem());
    bw = std::max(bw, *hi - *lo);
  }
  return bw;
}

// Every face used by one element only is in exactly one named surface, and no face is shared by 3 elements.
void expect_boundary_is_named(const Mesh& m) {
  std::map<std::vector<int>, int> count;
  auto key = [&](const Facet& f) {
    std::vector<int> k;
    for (int l : facet_local_nodes(m.type, f.local)) k.push_back(m.element(f.element)[l]);
    std::sort(k.begin(), k.end());
    return k;
  };
  for (int e = 0; e < m.num_elements(); ++e)
    for (int l = 0; l < 6; ++l) ++count[key({e, l})];
  std::map<std::vector<int>, int> named;
  for (const auto& [name, facets] : m.surfaces)
    for (const Facet& f : facets) ++named[key(f)];
  for (const auto& [k, c] : count) {
    EXPECT_LE(c, 2);
    EXPECT_EQ(named.count(k) ? named[k] : 0, c == 1 ? 1 : 0);
  }
  for (const auto& [k, c] : named) EXPECT_TRUE(count.count(k)) << "named facet is not an element facet";
}

double min_node_distance(const Mesh& m) {
  double d = INFINITY;
  for (int a = 0; a < m.num_nodes(); ++a)
    for (int b = a + 1; b < m.num_nodes(); ++b) d = std::min(d, norm(sub(m.nodes[a], m.nodes[b])));
  return d;
}

double exact_volume(const CylinderSpec& s) {
  return std::numbers::pi * (s.outer_radius * s.outer_radius - s.inner_radius * s.inner_radius) *
         (s.theta1 - s.theta0) / 360.0 * s.length;
}

void expect_invalid(void (*change)(CylinderSpec&), const std::string& text) {
  CylinderSpec s;
  change(s);
  std::string what = "(no exception)";
  try {
    make_cylinder(s);
  } catch (const std::invalid_argument& e) {
    what = e.what();
  }
  EXPECT_NE(what.find(text), std::string::npos) << "message: " << what;
}

TEST(Cylinder, FullRingCountsAndTopology) {
  for (auto [na, nr, nk] : {std::array<int, 3>{12, 2, 3}, {3, 1, 1}, {4, 6, 2}, {8, 3, 10}}) {
    CylinderSpec s;
    s.n_around = na;
    s.n_radial = nr;
    s.n_axial = nk;
    const Mesh m = make_cylinder(s);
    EXPECT_EQ(m.dim, 3);
    EXPECT_EQ(m.type, ElementType::Hex8);
    EXPECT_EQ(m.num_nodes(), na * (nr + 1) * (nk + 1));
    EXPECT_EQ(m.num_elements(), na * nr * nk);
    EXPECT_GT(min_node_distance(m), 1e-3);  // the seam nodes are shared, not duplicated
    EXPECT_EQ(m.surfaces.count("start") + m.surfaces.count("end"), 0u);
    EXPECT_EQ(m.surfaces.at("outer").size(), static_cast<size_t>(na * nk));
    EXPECT_EQ(m.surfaces.at("ymin").size(), static_cast<size_t>(na * nr));
    EXPECT_EQ(m.node_sets.at("ymax").size(), static_cast<size_t>(na * (nr + 1)));
    EXPECT_EQ(m.node_sets.at("all").size(), m.nodes.size());
    EXPECT_EQ(m.element_sets.at("all").size(), static_cast<size_t>(na * nr * nk));
    EXPECT_NO_THROW(check_element_orientation(m));
    expect_boundary_is_named(m);
  }
}

TEST(Cylinder, PartialSpanCountsAndOrientation) {
  const std::vector<CylinderSpec> specs = {{0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2, 6, 3, 0.0, 90.0},
                                           {1.0, -3.0, 0.5, 0.35, 0.3, 0.32, 1, 3, 2, -45.0, 300.0},
                                           {0.0, 0.3, -0.175, 0.35, 0.01, 0.3, 5, 1, 4, 200.0, 300.0}};
  for (const auto& s : specs) {
    const Mesh m = make_cylinder(s);
    EXPECT_EQ(m.num_nodes(), (s.n_around + 1) * (s.n_radial + 1) * (s.n_axial + 1));
    EXPECT_EQ(m.surfaces.at("start").size(), static_cast<size_t>(s.n_radial * s.n_axial));
    EXPECT_EQ(m.node_sets.at("end").size(), static_cast<size_t>((s.n_radial + 1) * (s.n_axial + 1)));
    EXPECT_NO_THROW(check_element_orientation(m)) << s.theta0 << ".." << s.theta1;
    for (int e = 0; e < m.num_elements(); ++e) EXPECT_GT(hex_volume(m, e), 0.0);
    expect_boundary_is_named(m);
  }
}

TEST(Cylinder, VolumeConvergesSecondOrder) {
  for (auto [t0, t1] : {std::array<double, 2>{0.0, 360.0}, {0.0, 90.0}}) {
    CylinderSpec s{0.2, -0.4, 1.0, 2.5, 0.3, 1.0, 1, 12, 1, t0, t1};
    double previous = 0.0;
    for (int level = 0; level < 4; ++level) {
      const double err = exact_volume(s) - mesh_volume(make_cylinder(s));
      EXPECT_GT(err, 0.0);
      if (level > 0) {
        EXPECT_NEAR(previous / err, 4.0, 0.1) << t0 << ".." << t1 << " level " << level;
      }
      previous = err;
      s.n_around *= 2;
      s.n_radial *= 2;
      s.n_axial *= 2;
    }
    EXPECT_LT(previous / exact_volume(s), 1e-3);
  }
}

TEST(Cylinder, NamedNodesLieOnTheirLoci) {
  const CylinderSpec s{0.5, 2.0, -1.0, 3.0, 0.4, 1.2, 2, 9, 3, 90.0, 180.0};
  const Mesh m = make_cylinder(s);
  auto radius = [&](int n) { return std::hypot(m.nodes[n][0] - s.cx, m.nodes[n][2] - s.cz); };
  for (int n : m.node_sets.at("inner")) EXPECT_NEAR(radius(n), s.inner_radius, 1e-12);
  for (int n : m.node_sets.at("outer")) EXPECT_NEAR(radius(n), s.outer_radius, 1e-12);
  for (int n : m.node_sets.at("ymin")) EXPECT_EQ(m.nodes[n][1], s.y0);
  for (int n : m.node_sets.at("ymax")) EXPECT_EQ(m.nodes[n][1], s.y0 + s.length);
  for (int n : m.node_sets.at("start")) EXPECT_EQ(m.nodes[n][0], s.cx);  // theta = 90: on +z of the axis
  for (int n : m.node_sets.at("end")) EXPECT_EQ(m.nodes[n][2], s.cz);    // theta = 180: on -x of the axis
  for (int n = 0; n < m.num_nodes(); ++n) {
    EXPECT_LE(m.nodes[n][0], s.cx + 1e-12);
    EXPECT_GE(m.nodes[n][2], s.cz - 1e-12);
    EXPECT_GE(m.nodes[n][1], s.y0);
    EXPECT_LE(m.nodes[n][1], s.y0 + s.length);
  }
}

TEST(Cylinder, FaceNormalsPointOutOfTheMaterial) {
  for (const CylinderSpec& s : {CylinderSpec{}, CylinderSpec{1.0, -1.0, 0.5, 2.0, 0.5, 1.0, 2, 8, 2, 30.0, 240.0}}) {
    const Mesh m = make_cylinder(s);
    const double t0 = s.theta0 * std::numbers::pi / 180.0, t1 = s.theta1 * std::numbers::pi / 180.0;
    const std::map<std::string, Vec> axis_and_ends = {{"ymin", {0, -1, 0}},
                                                      {"ymax", {0, 1, 0}},
                                                      {"start", {std::sin(t0), 0, -std::cos(t0)}},
                                                      {"end", {-std::sin(t1), 0, std::cos(t1)}}};
    for (const auto& [name, facets] : m.surfaces)
      for (const Facet& f : facets) {
        const auto [n, c] = face_normal_and_centroid(m, f);
        const Vec unit{n[0] / norm(n), n[1] / norm(n), n[2] / norm(n)};
        EXPECT_GT(dot(sub(c, centroid(m, m.element(f.element), {0, 1, 2, 3, 4, 5, 6, 7})), n), 0.0) << name;
        const Vec radial{c[0] - s.cx, 0.0, c[2] - s.cz};
        if (name == "inner") {
          EXPECT_GT(-dot(unit, radial) / norm(radial), 0.99);  // towards the axis
        }
        if (name == "outer") {
          EXPECT_GT(dot(unit, radial) / norm(radial), 0.99);
        }
        if (axis_and_ends.count(name)) {
          EXPECT_NEAR(dot(unit, axis_and_ends.at(name)), 1.0, 1e-12) << name;
        }
      }
  }
}

TEST(Cylinder, EndSectionMatchesTheAnnulusInTheXZPlane) {
  const CylinderSpec c{0.3, -0.2, 0.0, 1.0, 0.5, 1.0, 3, 10, 2, -60.0, 120.0};
  const Mesh cyl = make_cylinder(c);
  const Mesh ann =
      make_annulus({c.cx, c.cz, c.inner_radius, c.outer_radius, c.n_radial, c.n_around, c.theta0, c.theta1});
  std::vector<std::array<double, 2>> a, b;
  for (int n : cyl.node_sets.at("ymin")) a.push_back({cyl.nodes[n][0], cyl.nodes[n][2]});
  for (const auto& p : ann.nodes) b.push_back({p[0], p[1]});
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
}

TEST(Cylinder, NumberingKeepsBandwidthSmall) {
  // roll-like: many nodes around, few across and along: ring folded, radial fastest
  EXPECT_LE(bandwidth(make_cylinder({0, 0, 0, 1, 0.5, 1, 2, 48, 3, 0, 360})), 2 * 3 * 4 + 3 + 1);
  EXPECT_LE(bandwidth(make_cylinder({0, 0, 0, 1, 0.5, 1, 2, 48, 3, 0, 90})), 3 * 4 + 3 + 1);
  EXPECT_LE(bandwidth(make_cylinder({0, 0, 0, 1, 0.5, 1, 8, 6, 40, 0, 360})), 6 * 9 + 6 + 2);
}

TEST(Cylinder, InvalidSpecsThrowNamingTheField) {
  using S = CylinderSpec;
  expect_invalid([](S& s) { s.length = 0.0; }, "length");
  expect_invalid([](S& s) { s.n_axial = 0; }, "n_axial");
  expect_invalid([](S& s) { s.inner_radius = -0.1; }, "inner_radius");
  expect_invalid([](S& s) { s.outer_radius = 0.5; }, "outer_radius");
  expect_invalid([](S& s) { s.n_radial = 0; }, "n_radial");
  expect_invalid([](S& s) { s.n_around = 2; }, "n_around");
  expect_invalid([](S& s) { s.theta1 = -10.0; }, "theta1");
  expect_invalid([](S& s) { s.theta0 = -1.0; }, "360");
  expect_invalid([](S& s) { s.y0 = NAN; }, "y0");
  expect_invalid([](S& s) { s.cz = NAN; }, "cx/cz");
  expect_invalid([](S& s) { s.outer_profile.points = {{0.0, 0.0}, {1.0, -0.6}}; }, "outer_profile");
}

// A grooved barrel: 0.2 smaller in radius at y = 1, back to the full radius at y = 2 — the outer nodes follow it at
// every axial node, the inner ones stay, the radial nodes share the wall evenly, every element stays positive.
TEST(Cylinder, AnOuterProfileMovesTheBarrelsSurfaceOnly) {
  CylinderSpec s;
  s.length = 2.0;
  s.n_axial = 4;
  s.outer_profile.points = {{0.0, 0.0}, {1.0, -0.2}, {2.0, 0.0}};
  const Mesh m = make_cylinder(s);
  EXPECT_NO_THROW(check_element_orientation(m));
  auto radius = [&](int n) { return std::hypot(m.nodes[n][0] - s.cx, m.nodes[n][2] - s.cz); };
  for (int n : m.node_sets.at("outer")) {
    const double y = m.nodes[static_cast<size_t>(n)][1];
    EXPECT_NEAR(radius(n), 1.0 - 0.2 * (1 - std::abs(y - 1.0)), 1e-12) << "y = " << y;
  }
  for (int n : m.node_sets.at("inner")) EXPECT_NEAR(radius(n), 0.5, 1e-12);
}

}  // namespace
}  // namespace rollsim::test_cylinder
