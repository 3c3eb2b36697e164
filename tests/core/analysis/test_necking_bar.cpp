// Simo's necking bar at a coarse size (samples/necking-bar-3d.json is the full one): one eighth of a round bar with
// the 98.2 % imperfection at mid-length, F-bar hexahedra at finite strain, each end pulled 3.5 mm (7 mm in all).
// The axial load rises, peaks before Considère's uniform bar would and falls (the geometric softening of the neck
// overtakes the saturating hardening), and after the peak the neck keeps shrinking while the end, unloading, does
// not; every load and radius is finite.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_necking_bar {

using namespace rollsim;
using json = nlohmann::json;

namespace {

constexpr double kR = 6.413, kNeck = 0.982;

json necking_bar(const std::string& formulation, double edge, int increments) {
  const json mesh = {{"type", "round_bar"}, {"radius", kR}, {"length", 26.667},     {"n_core", 2},
                     {"n_ring", 1},         {"n_axial", 6}, {"axial_grading", 1.3}, {"neck_ratio", kNeck}};
  return {{"name", "necking"},
          {"dimension", 3},
          {"materials",
           {{{"name", "steel"},
             {"E", 206900.0},
             {"nu", 0.29},
             {"yield_stress", 450.0},
             {"hardening_modulus", 129.24},
             {"saturation_stress", 715.0},
             {"saturation_exponent", 16.93}}}},
          {"bodies",
           {{{"name", "bar"},
             {"material", "steel"},
             {"formulation", formulation},
             {"kinematics", "finite"},
             {"mesh", mesh}}}},
          {"boundary_conditions",
           {{{"type", "symmetry"}, {"body", "bar"}, {"set", "xmin"}, {"normal", "x"}},
            {{"type", "symmetry"}, {"body", "bar"}, {"set", "ymin"}, {"normal", "y"}},
            {{"type", "symmetry"}, {"body", "bar"}, {"set", "zmin"}, {"normal", "z"}},
            {{"type", "displacement"}, {"body", "bar"}, {"set", "zmax"}, {"uz", edge}}}},
          {"analysis", {{"increments", increments}}}};
}

struct Point {
  double edge = 0;      // the end's axial displacement [mm]
  double load = 0;      // whole bar [N]
  double neck = kNeck;  // current radius at the neck / R
  double end = 1;       // current radius at the end / R
};

/// The surface node on the x axis at height z (the mesh's nodes lie exactly there).
int surface_node(const Mesh& m, double z) {
  int best = -1;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (std::abs(m.nodes[n][1]) < 1e-12 && std::abs(m.nodes[n][2] - z) < 1e-9 &&
        (best < 0 || m.nodes[n][0] > m.nodes[best][0]))
      best = n;
  return best;
}

std::vector<Point> curve(const std::string& formulation, double edge, int increments) {
  const Project p = parse_project(necking_bar(formulation, edge, increments).dump(), "necking.json");
  const Model m = build_model(p);
  const Results r = run_project(p, m);
  EXPECT_EQ(r.status.status, Status::converged) << r.status.message;
  const Mesh& mesh = m.bodies[0].mesh;
  const int neck = surface_node(mesh, 0.0), end = surface_node(mesh, 26.667);
  std::vector<Point> out{Point{}};
  for (const IncrementResults& inc : r.increments) {
    const BodyResults& b = inc.bodies.at(0);
    Point q;
    for (int n : mesh.node_sets.at("zmax")) q.load += 4 * b.nodal_force[3 * n + 2];
    q.edge = b.displacement[3 * end + 2];
    q.neck = (mesh.nodes[neck][0] + b.displacement[3 * neck]) / kR;
    q.end = (mesh.nodes[end][0] + b.displacement[3 * end]) / kR;
    out.push_back(q);
  }
  return out;
}

/// Considère's maximum load of a uniform bar of section area A (uniaxial stress, logarithmic strains): the maximum
/// over the plastic strain ε_p of σ_y(ε_p) A exp(−ε_p − 2ν σ_y / E), and the edge displacement L/2 (exp(ε) − 1)
/// where it is reached, ε = ε_p + σ_y / E.
std::pair<double, double> considere(double area) {
  auto flow = [](double e) { return 450.0 + 129.24 * e + 265.0 * (1 - std::exp(-16.93 * e)); };
  double best = 0, edge = 0;
  for (double e = 1e-4; e < 0.5; e += 1e-4) {
    const double s = flow(e), load = s * area * std::exp(-e - 2 * 0.29 * s / 206900.0);
    if (load > best) best = load, edge = 26.667 * (std::exp(e + s / 206900.0) - 1);
  }
  return {best, edge};
}

}  // namespace

TEST(NeckingBar, LoadPeaksAndTheNeckShrinksAfterItWhileTheEndUnloads) {
  const std::vector<Point> c = curve("bbar", 3.5, 14);
  ASSERT_GE(c.size(), 15u);  // cut-back steps add increments
  EXPECT_NEAR(c.back().edge, 3.5, 1e-9);
  size_t peak = 0;
  for (size_t i = 0; i < c.size(); ++i) {
    ASSERT_TRUE(std::isfinite(c[i].load) && std::isfinite(c[i].neck) && std::isfinite(c[i].end)) << i;
    if (c[i].load > c[peak].load) peak = i;
  }
  // a maximum inside the run, near Considère's: a uniform bar of the mesh's section (the inscribed polygon, 4
  // segments a quarter) peaks at u = 3.56 mm; the weakest section (0.982² of it) bounds the imperfect bar from below
  const auto [uniform, edge] = considere(4 * 2 * kR * kR * std::sin(M_PI / 8));
  EXPECT_GT(peak, 2u);
  EXPECT_LT(peak, c.size() - 2);
  EXPECT_LT(c[peak].edge, edge);
  EXPECT_GT(c[peak].edge, 0.6 * edge);
  EXPECT_GT(c[peak].load, 0.98 * kNeck * kNeck * uniform);
  EXPECT_LT(c[peak].load, 1.02 * uniform);
  EXPECT_LT(c.back().load, 0.99 * c[peak].load);
  // before the peak the bar thins almost uniformly; after it the neck runs away and the end springs back
  EXPECT_NEAR(c[peak].neck / kNeck, c[peak].end, 0.05);
  EXPECT_LT(c.back().neck, c[peak].neck - 0.03);
  EXPECT_GT(c.back().end, c[peak].end - 0.005);
}

TEST(NeckingBar, FullIntegrationLocksTheNeck) {
  // the same bar with full 2×2×2 integration: isochoric plastic flow locks, the load is still rising at 3.5 mm and
  // the neck has shrunk far less than with F-bar
  const std::vector<Point> fbar = curve("bbar", 3.5, 14);
  const std::vector<Point> full = curve("full", 3.5, 14);
  EXPECT_GT(full.back().load, full[full.size() - 2].load);
  EXPECT_GT(full.back().load, fbar.back().load);
  EXPECT_GT(full.back().neck, fbar.back().neck + 0.03);
}

}  // namespace test_necking_bar
