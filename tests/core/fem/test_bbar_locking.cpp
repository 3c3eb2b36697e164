// Near-incompressibility: a thick cylinder under internal pressure (plane strain, Lame's solution)
// at nu = 0.4999. Full integration locks (radial displacement far too small), B-bar does not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/LinearStatic.h"
#include "mesh/Annulus.h"
#include "mesh/Cylinder.h"
#include "solve/SolverStrategy.h"

namespace test_bbar_locking {

using namespace rollsim;

namespace {

constexpr double A = 1.0, B = 2.0, P = 1.0, E = 1000.0;

double lame_inner_displacement(double nu) {
  return (1 + nu) * P * A * A / (E * (B * B - A * A)) * ((1 - 2 * nu) * A + B * B / A);
}

/// Radial displacement of the inner surface (mean over its nodes) of a quarter cylinder: 2D annulus, or
/// 3D cylinder (axis y) held in plane strain by uy = 0 on both end faces.
double inner_displacement(int dim, double nu, Formulation f, int n) {
  Model m;
  m.dim = dim;
  const int radial = dim == 2 ? 1 : 2;  // in-plane components: (x, y) in 2D, (x, z) in 3D
  const Mesh mesh = dim == 2 ? make_annulus({0.0, 0.0, A, B, n, 2 * n, 0.0, 90.0})
                             : make_cylinder({0.0, 0.0, 0.0, 0.5, A, B, n, 2 * n, 1, 0.0, 90.0});
  m.bodies.push_back({"tube", mesh, {E, nu}, "m", f});
  DisplacementBC start{0, "start", mesh.node_sets.at("start"), {}}, end{0, "end", mesh.node_sets.at("end"), {}};
  start.value[radial] = 0.0;
  end.value[0] = 0.0;
  m.displacements = {start, end};
  if (dim == 3)
    for (const char* face : {"ymin", "ymax"}) {
      DisplacementBC axial{0, face, mesh.node_sets.at(face), {}};
      axial.value[1] = 0.0;
      m.displacements.push_back(axial);
    }
  m.pressures.push_back({0, "inner", P});
  auto solver = make_solver("direct", {});
  const Results r = run_linear_static(m, *solver);
  double sum = 0;
  const auto& inner = mesh.node_sets.at("inner");
  for (int node : inner) {
    const auto& x = mesh.nodes[node];
    const double rad = std::hypot(x[0], x[radial]);
    const double* u = r.bodies[0].displacement.data() + dim * node;
    sum += (u[0] * x[0] + u[radial] * x[radial]) / rad;
  }
  return sum / static_cast<double>(inner.size());
}

}  // namespace

TEST(BBarLocking, FullIntegrationLocksBBarDoesNot) {
  const double nu = 0.4999, exact = lame_inner_displacement(nu);
  for (int n : {4, 8, 16}) {
    const double full = inner_displacement(2, nu, Formulation::Full, n) / exact;
    const double bbar = inner_displacement(2, nu, Formulation::BBar, n) / exact;
    std::printf("  %2d x %2d elements: u_r(a)/exact  full %.4f  B-bar %.4f\n", n, 2 * n, full, bbar);
    EXPECT_LT(full, 0.8) << "full integration should lock at nu = 0.4999";
    EXPECT_NEAR(bbar, 1.0, 0.01);
  }
}

TEST(BBarLocking, Hex8FullIntegrationLocksBBarDoesNot) {
  const double nu = 0.4999, exact = lame_inner_displacement(nu);
  const double full = inner_displacement(3, nu, Formulation::Full, 8) / exact;
  const double bbar = inner_displacement(3, nu, Formulation::BBar, 8) / exact;
  std::printf("  H8 8 x 16 elements: u_r(a)/exact  full %.4f  B-bar %.4f\n", full, bbar);
  EXPECT_LT(full, 0.8);
  EXPECT_NEAR(bbar, 1.0, 0.01);
}

TEST(BBarLocking, BothAgreeAtModerateNu) {
  const double exact = lame_inner_displacement(0.3);
  EXPECT_NEAR(inner_displacement(2, 0.3, Formulation::Full, 16) / exact, 1.0, 0.01);
  EXPECT_NEAR(inner_displacement(2, 0.3, Formulation::BBar, 16) / exact, 1.0, 0.01);
}

}  // namespace test_bbar_locking
