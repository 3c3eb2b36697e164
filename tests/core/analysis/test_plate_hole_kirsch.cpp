// Plate with a hole in uniaxial tension: the stress concentration at the hole edge approaches
// Kirsch's value 3 (infinite plate) as the plate grows around a hole meshed the same way.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/LinearStatic.h"
#include "mesh/PlateWithHole.h"
#include "solve/SolverStrategy.h"

namespace test_plate_hole_kirsch {

using namespace rollsim;

namespace {

/// sigma_yy / applied stress at A = (a, 0) for a quarter plate of half-size W, tension 1 along y.
double concentration(double W, int n_radial, double grading) {
  Model m;
  m.dim = 2;
  const Mesh mesh = make_plate_with_hole({W, W, 1.0, 48, n_radial, grading});
  m.bodies.push_back({"plate", mesh, {1000.0, 0.3}, "m", Formulation::Full});
  DisplacementBC left{0, "left", mesh.node_sets.at("left"), {}}, bottom{0, "bottom", mesh.node_sets.at("bottom"), {}};
  left.value[0] = 0.0;
  bottom.value[1] = 0.0;
  m.displacements = {left, bottom};
  m.pressures.push_back({0, "top", -1.0});  // tension of 1 on y = W
  auto solver = make_solver("direct", {});
  const Results r = run_linear_static(m, *solver);
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (std::abs(mesh.nodes[n][0] - 1.0) < 1e-12 && std::abs(mesh.nodes[n][1]) < 1e-12)
      return r.bodies[0].nodal_stress[n][1];
  ADD_FAILURE() << "node A not found";
  return 0;
}

}  // namespace

TEST(PlateHoleKirsch, ConcentrationApproachesThree) {
  struct Case {
    double W;
    int n_radial;
    double grading;
  };
  double prev_err = 1e9;
  for (const Case c : {Case{2.5, 16, 1.05}, Case{5.0, 26, 1.08}, Case{10.0, 36, 1.1}, Case{20.0, 44, 1.12}}) {
    const double k = concentration(c.W, c.n_radial, c.grading);
    const double err = std::abs(k - 3.0);
    std::printf("  W/a = %5.1f: sigma_yy(A)/sigma = %.4f  (Kirsch: 3)\n", c.W, k);
    EXPECT_LT(err, prev_err);
    prev_err = err;
  }
  EXPECT_LT(prev_err, 0.05);
}

}  // namespace test_plate_hole_kirsch
