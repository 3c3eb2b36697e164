// Tests of the structured rectangle (Q4) / box (H8) generator: counts, orientation, exact area/volume, named
// sets on their loci, outward normals, numbering along the shortest direction first.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/StructuredBlock.h"

namespace rollsim::test_structured_block {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Q4: shoelace (exact for a bilinear quad). H8: 2x2x2 Gauss rule (exact for a trilinear hex).
double element_measure(const Mesh& m, int e) {
  const int* c = m.element(e);
  if (m.type == ElementType::Quad4) {
    double a = 0.0;
    for (int k = 0; k < 4; ++k) {
      const Vec &p = m.nodes[c[k]], &q = m.nodes[c[(k + 1) % 4]];
      a += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    }
    return a;
  }
  static const int sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  double volume = 0.0;
  for (int q = 0; q < 8; ++q) {
    std::array<Vec, 3> col{};  // col[a] = d x / d xi_a
    for (int n = 0; n < 8; ++n)
      for (int a = 0; a < 3; ++a) {
        double dn = 0.125 * sign[n][a];
        for (int b = 0; b < 3; ++b)
          if (b != a) dn *= 1.0 + sign[n][b] * sign[q][b] * g;
        for (int d = 0; d < 3; ++d) col[a][d] += dn * m.nodes[c[n]][d];
      }
    volume += dot(col[0], cross(col[1], col[2]));
  }
  return volume;
}

double mesh_measure(const Mesh& m) {
  double v = 0.0;
  for (int e = 0; e < m.num_elements(); ++e) v += element_measure(m, e);
  return v;
}

// Outward normal of a facet (edge: right-hand side; face: right-hand rule), not normalised.
Vec facet_normal(const Mesh& m, const Facet& f) {
  const auto loc = facet_local_nodes(m.type, f.local);
  auto p = [&](int k) { return m.nodes[m.element(f.element)[loc[k]]]; };
  if (m.type == ElementType::Quad4) return {p(1)[1] - p(0)[1], p(0)[0] - p(1)[0], 0.0};
  return cross(sub(p(2), p(0)), sub(p(3), p(1)));
}

int bandwidth(const Mesh& m) {
  int bw = 0;
  for (int e = 0; e < m.num_elements(); ++e) {
    const auto [lo, hi] = std::minmax_element(m.element(e), m.element(e) + m.nodes_per_elem());
    bw = std::max(bw, *hi - *lo);
  }
  return bw;
}

// Every facet used by one element only is in exactly one named surface.
void expect_boundary_is_named(const Mesh& m) {
  std::map<std::vector<int>, int> count;
  auto key = [&](const Facet& f) {
    std::vector<int> k;
    for (int l : facet_local_nodes(m.type, f.local)) k.push_back(m.element(f.element)[l]);
    std::sort(k.begin(), k.end());
    return k;
  };
  const int facets_per_element = m.dim == 2 ? 4 : 6;
  for (int e = 0; e < m.num_elements(); ++e)
    for (int l = 0; l < facets_per_element; ++l) ++count[key({e, l})];
  std::map<std::vector<int>, int> named;
  for (const auto& [name, facets] : m.surfaces)
    for (const Facet& f : facets) ++named[key(f)];
  for (const auto& [k, c] : count) {
    EXPECT_LE(c, 2);
    EXPECT_EQ(named.count(k) ? named[k] : 0, c == 1 ? 1 : 0);
  }
}

BlockSpec block2(int nx, int ny) {
  BlockSpec s;
  s.dim = 2;
  s.n = {nx, ny, 1};
  s.size = {3.0, 1.5, 1.0};
  s.origin = {-1.0, 2.0, 0.0};
  return s;
}

BlockSpec block3(int nx, int ny, int nz) {
  BlockSpec s;
  s.dim = 3;
  s.n = {nx, ny, nz};
  s.size = {2.0, 0.7, 1.3};
  s.origin = {0.5, -1.0, 3.0};
  return s;
}

TEST(StructuredBlock, CountsOrientationAndArea2D) {
  for (auto [nx, ny] : {std::array<int, 2>{1, 1}, {10, 3}, {3, 10}, {4, 4}}) {
    const BlockSpec s = block2(nx, ny);
    const Mesh m = make_block(s);
    EXPECT_EQ(m.dim, 2);
    EXPECT_EQ(m.type, ElementType::Quad4);
    EXPECT_EQ(m.num_nodes(), (nx + 1) * (ny + 1));
    EXPECT_EQ(m.num_elements(), nx * ny);
    EXPECT_EQ(m.element_sets.at("all").size(), static_cast<size_t>(nx * ny));
    EXPECT_EQ(m.node_sets.at("all").size(), m.nodes.size());
    EXPECT_NO_THROW(check_element_orientation(m));
    EXPECT_NEAR(mesh_measure(m), s.size[0] * s.size[1], 1e-12);
    expect_boundary_is_named(m);
    EXPECT_EQ(m.surfaces.size(), 4u);
  }
}

TEST(StructuredBlock, CountsOrientationAndVolume3D) {
  for (auto [nx, ny, nz] : {std::array<int, 3>{1, 1, 1}, {6, 3, 2}, {2, 5, 3}, {3, 2, 7}}) {
    const BlockSpec s = block3(nx, ny, nz);
    const Mesh m = make_block(s);
    EXPECT_EQ(m.dim, 3);
    EXPECT_EQ(m.type, ElementType::Hex8);
    EXPECT_EQ(m.num_nodes(), (nx + 1) * (ny + 1) * (nz + 1));
    EXPECT_EQ(m.num_elements(), nx * ny * nz);
    EXPECT_NO_THROW(check_element_orientation(m));
    for (int e = 0; e < m.num_elements(); ++e) EXPECT_GT(element_measure(m, e), 0.0);
    EXPECT_NEAR(mesh_measure(m), s.size[0] * s.size[1] * s.size[2], 1e-12);
    expect_boundary_is_named(m);
    EXPECT_EQ(m.surfaces.size(), 6u);
  }
}

TEST(StructuredBlock, NamedNodesLieOnTheirFaces) {
  for (const BlockSpec& s : {block2(5, 3), block3(4, 3, 2)}) {
    const Mesh m = make_block(s);
    const char* names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
    for (int d = 0; d < s.dim; ++d) {
      size_t on_face = 1;
      for (int k = 0; k < s.dim; ++k)
        if (k != d) on_face *= static_cast<size_t>(s.n[k] + 1);
      for (int side = 0; side < 2; ++side) {
        const double x = s.origin[d] + side * s.size[d];
        const auto& set = m.node_sets.at(names[d][side]);
        EXPECT_EQ(set.size(), on_face) << names[d][side];
        for (int n : set) EXPECT_NEAR(m.nodes[n][d], x, 1e-12) << names[d][side];
        const auto count =
            std::count_if(m.nodes.begin(), m.nodes.end(), [&](const Vec& p) { return std::abs(p[d] - x) < 1e-12; });
        EXPECT_EQ(static_cast<size_t>(count), on_face) << names[d][side];
      }
    }
  }
}

TEST(StructuredBlock, FacetNormalsPointOutward) {
  const std::map<std::string, Vec> expected = {{"xmin", {-1, 0, 0}}, {"xmax", {1, 0, 0}},  {"ymin", {0, -1, 0}},
                                               {"ymax", {0, 1, 0}},  {"zmin", {0, 0, -1}}, {"zmax", {0, 0, 1}}};
  for (const BlockSpec& s : {block2(4, 3), block3(3, 2, 2)}) {
    const Mesh m = make_block(s);
    for (const auto& [name, facets] : m.surfaces)
      for (const Facet& f : facets) {
        const Vec n = facet_normal(m, f);
        const double len = std::sqrt(dot(n, n));
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(n[d] / len, expected.at(name)[d], 1e-12) << name;
      }
  }
}

TEST(StructuredBlock, NumbersAlongTheShortestDirectionFirst) {
  // 2D 10 x 3: y has fewer nodes, so node 1 is one step up in y from node 0
  const Mesh m2 = make_block(block2(10, 3));
  EXPECT_NEAR(m2.nodes[1][0], m2.nodes[0][0], 1e-12);
  EXPECT_NEAR(m2.nodes[1][1] - m2.nodes[0][1], 1.5 / 3, 1e-12);
  EXPECT_EQ(bandwidth(m2), 3 + 2);
  EXPECT_EQ(bandwidth(make_block(block2(3, 10))), 3 + 2);
  // 3D 6 x 3 x 2: z fastest, then y, then x
  const Mesh m3 = make_block(block3(6, 3, 2));
  EXPECT_NEAR(m3.nodes[1][2] - m3.nodes[0][2], 1.3 / 2, 1e-12);
  EXPECT_NEAR(m3.nodes[3][1] - m3.nodes[0][1], 0.7 / 3, 1e-12);
  EXPECT_EQ(bandwidth(m3), 1 + 3 + 3 * 4);
}

TEST(StructuredBlock, GradingAlongXMovesNodesOnlyAndKeepsTheLength) {
  BlockSpec s = block2(6, 2);
  const Mesh uniform = make_block(s);
  for (const double g : {1.3, 1.0 / 1.3}) {
    SCOPED_TRACE(g);
    s.grading[0] = g;
    const Mesh m = make_block(s);
    EXPECT_EQ(m.connectivity, uniform.connectivity);
    EXPECT_NEAR(mesh_measure(m), mesh_measure(uniform), 1e-12);
    // the bottom row of nodes, left to right: element sizes fall by g from each element to the next
    std::vector<double> x;
    for (const Vec& p : m.nodes)
      if (p[1] == s.origin[1]) x.push_back(p[0]);
    std::sort(x.begin(), x.end());
    ASSERT_EQ(x.size(), 7u);
    EXPECT_EQ(x.front(), s.origin[0]);
    EXPECT_EQ(x.back(), s.origin[0] + s.size[0]);
    for (size_t i = 0; i + 2 < x.size(); ++i) EXPECT_NEAR((x[i + 1] - x[i]) / (x[i + 2] - x[i + 1]), g, 1e-12);
  }
  EXPECT_EQ(graded_fraction(3, 6, 1.0), 3.0 / 6);
  s.grading[0] = 0.0;
  EXPECT_THROW(make_block(s), std::invalid_argument);
}

TEST(StructuredBlock, GradingAlongYAndZBiasesThoseAxesAlone) {
  BlockSpec s;
  s.dim = 3;
  s.n = {2, 4, 5};
  s.size = {1.0, 2.0, 3.0};
  s.grading = {1.0, 1.5, 0.7};
  const Mesh m = make_block(s);
  const auto sorted = [&](int axis) {
    std::vector<double> v;
    for (const Vec& p : m.nodes) v.push_back(p[static_cast<size_t>(axis)]);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  };
  EXPECT_EQ(sorted(0), (std::vector<double>{0.0, 0.5, 1.0}));  // x stays uniform
  for (const int axis : {1, 2}) {
    const std::vector<double> c = sorted(axis);
    ASSERT_EQ(c.size(), static_cast<size_t>(s.n[static_cast<size_t>(axis)] + 1));
    EXPECT_EQ(c.back(), s.size[static_cast<size_t>(axis)]);
    for (size_t i = 0; i + 2 < c.size(); ++i)
      EXPECT_NEAR((c[i + 1] - c[i]) / (c[i + 2] - c[i + 1]), s.grading[static_cast<size_t>(axis)], 1e-12);
  }
  s.grading[2] = -1.0;
  try {
    make_block(s);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("grading along z"), std::string::npos) << e.what();
  }
}

// An ALE window's columns: x planes given one by one (the rolling process's ale_grading), y and z as before; planes
// that are not nx + 1 increasing coordinates are refused.
TEST(StructuredBlock, ExplicitXPlanesPlaceTheNodesAlongX) {
  BlockSpec s;
  s.dim = 3;
  s.n = {3, 1, 2};
  s.size = {9.0, 1.0, 2.0};
  s.x_planes = {-4.0, -1.0, 0.0, 0.5};
  const Mesh m = make_block(s);
  std::vector<double> x;
  for (const Vec& p : m.nodes) x.push_back(p[0]);
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  EXPECT_EQ(x, s.x_planes);
  EXPECT_EQ(m.num_elements(), 6);
  for (const std::vector<double>& bad : {std::vector<double>{-4.0, -1.0, 0.5}, std::vector<double>{-4, 0, -1, 0.5}}) {
    s.x_planes = bad;
    EXPECT_THROW(make_block(s), std::invalid_argument);
  }
}

}  // namespace
}  // namespace rollsim::test_structured_block
