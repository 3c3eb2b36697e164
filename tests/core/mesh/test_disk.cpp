// Tests of the solid disk / solid cylinder generator (the o-grid over whole quarters): counts, orientation, merged
// quarter edges, the area against π R², the named sets, validation; and through the pipeline, a quarter disk (2D) and
// a quarter cylinder (3D) under a uniform outer pressure, held by symmetry on its straight edges, carry the exact
// uniform stress −p, which only right sets and outward facets on the round surface give.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>

#include "analysis/Results.h"
#include "mesh/Disk.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace rollsim::test_disk {
namespace {

DiskSpec spec(int dim, double theta0, double theta1) {
  DiskSpec s;
  s.dim = dim;
  s.c0 = 1.0;
  s.c1 = -2.0;
  s.radius = 3.0;
  s.n_core = 3;
  s.n_ring = 2;
  s.theta0 = theta0;
  s.theta1 = theta1;
  s.length = 2.0;
  s.n_axial = 2;
  return s;
}

/// The node's (section) coordinates about the centre: 2D (x, y), 3D (x, z).
std::array<double, 2> about_centre(const DiskSpec& s, const Mesh& m, int n) {
  const auto& x = m.nodes[static_cast<size_t>(n)];
  return {x[0] - s.c0, (s.dim == 2 ? x[1] : x[2]) - s.c1};
}

double quad_area(const Mesh& m, int e) {
  const int* c = m.element(e);
  double a = 0;
  for (int k = 0; k < 4; ++k) {
    const auto &p = m.nodes[c[k]], &q = m.nodes[c[(k + 1) % 4]];
    a += 0.5 * (p[0] * q[1] - q[0] * p[1]);
  }
  return a;
}

}  // namespace

TEST(Disk, CountsOrientationAndMergedQuarterEdges) {
  for (int dim : {2, 3})
    for (auto [t0, t1] : {std::pair{0.0, 360.0}, {90.0, 270.0}, {-90.0, 0.0}}) {
      const DiskSpec s = spec(dim, t0, t1);
      const Mesh m = make_disk(s);
      const int quarters = static_cast<int>((t1 - t0) / 90), per_quarter = 3 * (3 + 2 * 2);
      const int layers = dim == 3 ? 3 : 1;
      EXPECT_EQ(m.num_elements(), quarters * per_quarter * (layers == 1 ? 1 : 2)) << dim << "D " << t0;
      EXPECT_NO_THROW(check_element_orientation(m)) << dim << "D " << t0;
      // distinct nodes: the quarters share their edges, every node is used
      std::set<std::array<long long, 3>> at;
      for (const auto& x : m.nodes)
        at.insert({std::llround(x[0] * 1e8), std::llround(x[1] * 1e8), std::llround(x[2] * 1e8)});
      EXPECT_EQ(at.size(), m.nodes.size()) << dim << "D " << t0;
      std::vector<char> used(m.nodes.size(), 0);
      for (int n : m.connectivity) used[static_cast<size_t>(n)] = 1;
      EXPECT_EQ(std::count(used.begin(), used.end(), 1), static_cast<long>(m.nodes.size()));
      ASSERT_EQ(m.node_sets.at("center").size(), static_cast<size_t>(layers));
      for (int n : m.node_sets.at("center")) {
        const auto p = about_centre(s, m, n);
        EXPECT_NEAR(std::hypot(p[0], p[1]), 0.0, 1e-12);
      }
    }
}

TEST(Disk, TheAreaApproachesPiRSquaredFromBelow) {
  double previous = 0;
  for (int n : {2, 4, 8}) {
    DiskSpec s = spec(2, 0, 360);
    s.n_core = n;
    s.n_ring = n;
    const Mesh m = make_disk(s);
    double area = 0;
    for (int e = 0; e < m.num_elements(); ++e) {
      EXPECT_GT(quad_area(m, e), 0.0);
      area += quad_area(m, e);
    }
    const double exact = std::numbers::pi * 9.0;
    EXPECT_LT(area, exact);
    EXPECT_GT(area, previous);
    previous = area;
    if (n == 8) EXPECT_NEAR(area, exact, 0.005 * exact);
  }
}

TEST(Disk, SurfacesLieWhereTheyAreNamed) {
  for (int dim : {2, 3}) {
    const DiskSpec s = spec(dim, 90, 270);  // the left half: start along +y, end along −y
    const Mesh m = make_disk(s);
    std::set<std::string> names;
    for (const auto& [name, facets] : m.surfaces) names.insert(name);
    const std::set<std::string> expected = dim == 2 ? std::set<std::string>{"outer", "start", "end"}
                                                    : std::set<std::string>{"outer", "start", "end", "ymin", "ymax"};
    EXPECT_EQ(names, expected);
    for (int n : m.node_sets.at("outer")) {
      const auto p = about_centre(s, m, n);
      EXPECT_NEAR(std::hypot(p[0], p[1]), 3.0, 1e-12);
    }
    for (int n : m.node_sets.at("start")) {
      const auto p = about_centre(s, m, n);
      EXPECT_NEAR(p[0], 0.0, 1e-12);
      EXPECT_GE(p[1], -1e-12);
    }
    for (int n : m.node_sets.at("end")) {
      const auto p = about_centre(s, m, n);
      EXPECT_NEAR(p[0], 0.0, 1e-12);
      EXPECT_LE(p[1], 1e-12);
    }
    if (dim == 3) {
      for (int n : m.node_sets.at("ymin")) EXPECT_NEAR(m.nodes[static_cast<size_t>(n)][1], 0.0, 1e-12);
      for (int n : m.node_sets.at("ymax")) EXPECT_NEAR(m.nodes[static_cast<size_t>(n)][1], 2.0, 1e-12);
    }
    EXPECT_EQ(m.surfaces.at("outer").size(), static_cast<size_t>(2 * 2 * 3 * (dim == 3 ? 2 : 1)));
  }
}

TEST(Disk, ASpecOffTheQuartersIsRefusedNamingTheField) {
  DiskSpec s = spec(2, 45, 360);
  try {
    make_disk(s);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("theta0 and theta1 must be multiples of 90"), std::string::npos) << e.what();
  }
  json p = {{"name", "d"},
            {"dimension", 2},
            {"materials", {{{"name", "m"}, {"E", 1.0}, {"nu", 0.3}}}},
            {"bodies",
             {{{"name", "b"},
               {"material", "m"},
               {"mesh",
                {{"type", "disk"},
                 {"center", {0, 0}},
                 {"radius", 1},
                 {"n_core", 2},
                 {"n_ring", 2},
                 {"start_angle", 30},
                 {"length", 2}}}}}}};
  try {
    build_model(parse_project(p.dump(), "d.json"));
    ADD_FAILURE() << "accepted";
  } catch (const ProjectError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bodies[0].mesh.start_angle: must be a multiple of 90"), std::string::npos) << what;
    EXPECT_NE(what.find("bodies[0].mesh.length: not allowed in a 2D model"), std::string::npos) << what;
  }
}

// A uniform pressure p on the round surface of a quarter disk held by symmetry on its straight edges: the polygonal
// boundary's consistent nodal forces are those of the uniform stress −p (in 3D −p in x and z, 0 along the free axis),
// which linear elements carry exactly.
TEST(Disk, AQuarterUnderOuterPressureCarriesTheExactUniformStress) {
  const double p = 5.0;
  for (int dim : {2, 3}) {
    json mesh = {{"type", "disk"}, {"center", {0, 0}}, {"radius", 2.0},  {"n_core", 3},
                 {"n_ring", 3},    {"start_angle", 0}, {"end_angle", 90}};
    if (dim == 3) mesh.update({{"length", 1.0}, {"n_axial", 2}});
    const char* section_y = dim == 2 ? "y" : "z";
    json bcs = {{{"type", "symmetry"}, {"body", "b"}, {"set", "start"}, {"normal", section_y}},
                {{"type", "symmetry"}, {"body", "b"}, {"set", "end"}, {"normal", "x"}},
                {{"type", "pressure"}, {"body", "b"}, {"surface", "outer"}, {"value", p}}};
    if (dim == 3) bcs.push_back({{"type", "symmetry"}, {"body", "b"}, {"set", "ymin"}, {"normal", "y"}});
    const json j = {{"name", "disk"},
                    {"dimension", dim},
                    {"materials", {{{"name", "m"}, {"E", 200.0}, {"nu", 0.3}}}},
                    {"bodies", {{{"name", "b"}, {"material", "m"}, {"mesh", mesh}}}},
                    {"boundary_conditions", bcs}};
    const Project project = parse_project(j.dump(), "disk.json");
    const Results r = run_project(project, build_model(project));
    ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
    const int in_section_y = dim == 2 ? 1 : 2;
    for (const auto& s : r.bodies[0].element_stress) {
      EXPECT_NEAR(s[0], -p, 1e-9 * p) << dim << "D";
      EXPECT_NEAR(s[static_cast<size_t>(in_section_y)], -p, 1e-9 * p) << dim << "D";
      for (size_t shear : {3, 4, 5}) EXPECT_NEAR(s[shear], 0.0, 1e-9 * p) << dim << "D";
      if (dim == 3) EXPECT_NEAR(s[1], 0.0, 1e-9 * p) << "3D: the free axial direction";
    }
  }
}

}  // namespace rollsim::test_disk
