// Tractions and body forces as consistent nodal forces: a uniform load's nodal forces add up to the load times the
// surface's area or the body's volume on distorted elements too, and split as ∫N over a rectangle; through the whole
// pipeline, a plane-strain column under a top traction has the exact displacement at every node, and under its
// weight approaches the exact one as the column thins.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/Results.h"
#include "fem/Loads.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_loads {

using namespace rollsim;

namespace {

/// One body of a block mesh (2D nx × ny over lx × ly; 3D with nz × lz), its nodes moved by `warp` (x, y, z → dx).
Model block(int dim, std::array<double, 3> (*warp)(const std::array<double, 3>&) = nullptr) {
  json mesh = {{"type", "block"}, {"nx", 3}, {"ny", 2}, {"lx", 3.0}, {"ly", 2.0}};
  if (dim == 3) mesh.update({{"nz", 2}, {"lz", 1.5}});
  const json p = {
      {"name", "b"},
      {"dimension", dim},
      {"materials", {{{"name", "m"}, {"E", 1.0}, {"nu", 0.3}}}},
      {"bodies", {{{"name", "b"}, {"material", "m"}, {"mesh", mesh}}}},
      {"boundary_conditions",
       {{{"type", "displacement"}, {"body", "b"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}, {"uz", 0.0}}}}};
  json q = p;
  if (dim == 2) q["boundary_conditions"][0].erase("uz");
  Model m = build_model(parse_project(q.dump(), "block.json"));
  if (warp)
    for (auto& x : m.bodies[0].mesh.nodes) {
      const auto d = warp(x);
      for (int k = 0; k < 3; ++k) x[static_cast<size_t>(k)] += d[static_cast<size_t>(k)];
    }
  return m;
}

std::array<double, 3> skew(const std::array<double, 3>& x) {  // every element a different quadrilateral; faces warp
  return {0.1 * x[1] * x[1], 0.15 * x[0] - 0.05 * x[0] * x[1], 0.1 * x[0] * x[1]};
}

Eigen::Vector3d total(const Eigen::VectorXd& F, int dim) {
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < F.size(); ++i) s[i % dim] += F[i];
  return s;
}

double volume(const Model& m) {  // Σ ∫ N dV over the nodes: the volume, as the body-force loads integrate it
  Model only = m;
  only.body_forces = {{0, {1.0, 0.0, 0.0}}};
  return total(external_nodal_load(only, 0), m.dim)[0];
}

}  // namespace

TEST(Loads, ATractionsNodalForcesAddUpToItTimesTheArea) {
  for (int dim : {2, 3}) {
    Model m = block(dim, skew);
    m.tractions = {{0, "ymax", {0.3, -1.2, dim == 3 ? 0.7 : 0.0}}};
    // the undeformed top's length (2D) or area (3D), as the traction's quadrature integrates it
    const double area = total(traction_nodal_load(m.bodies[0].mesh, {0, "ymax", {1.0, 0.0, 0.0}}), dim)[0];
    const Eigen::Vector3d f = total(external_nodal_load(m, 0), dim);
    EXPECT_NEAR(f[0], 0.3 * area, 1e-12) << dim;
    EXPECT_NEAR(f[1], -1.2 * area, 1e-12) << dim;
    if (dim == 3) EXPECT_NEAR(f[2], 0.7 * area, 1e-12);
    if (dim == 2) EXPECT_NEAR(area, std::hypot(3.0, 3 * 0.15 - 0.05 * 3 * 2), 1e-12);  // the warped top is straight
  }
}

TEST(Loads, OnARectangleTheySplitAsTheShapeFunctionsIntegrals) {
  Model m = block(2);
  m.tractions = {{0, "ymax", {0.0, -2.0, 0.0}}};  // 3 edges of length 1: end nodes 1, inner nodes 2
  const Eigen::VectorXd F = external_nodal_load(m, 0);
  const Mesh& mesh = m.bodies[0].mesh;
  for (int n : mesh.node_sets.at("ymax")) {
    const bool end = mesh.nodes[static_cast<size_t>(n)][0] == 0.0 || mesh.nodes[static_cast<size_t>(n)][0] == 3.0;
    EXPECT_DOUBLE_EQ(F[2 * n + 1], end ? -1.0 : -2.0);
  }
  m.tractions.clear();
  m.body_forces = {{0, {0.0, -4.0, 0.0}}};  // unit squares: a quarter of 4 per element to each of its corners
  const Eigen::VectorXd G = external_nodal_load(m, 0);
  EXPECT_DOUBLE_EQ(G[1], -1.0);  // the corner node (0, 0) has one element
  EXPECT_NEAR(total(G, 2)[1], -4.0 * 6.0, 1e-12);
}

TEST(Loads, ABodyForcesNodalForcesAddUpToItTimesTheVolume) {
  for (int dim : {2, 3}) {
    const Model plain = block(dim);
    EXPECT_NEAR(volume(plain), dim == 2 ? 6.0 : 9.0, 1e-12);
    Model m = block(dim, skew);
    m.body_forces = {{0, {0.5, 2.0, dim == 3 ? -1.0 : 0.0}}};
    const Eigen::Vector3d f = total(external_nodal_load(m, 0), dim);
    const double v = volume(m);
    EXPECT_GT(std::abs(v - volume(plain)), 0.1) << "the warp changes the volume";
    EXPECT_NEAR(f[1], 2.0 * v, 1e-12);
    if (dim == 3) EXPECT_NEAR(f[2], -v, 1e-12);
  }
}

namespace {
/// A plane-strain column 1 wide and H = 10 high (1 × ny elements), its base on rollers (uy = 0) and one corner
/// pinned, its sides free, under a body force −b along y and a top traction −t: σyy(y) alone (σxx = 0, σzz = ν σyy),
/// so uy(y) = −(1 − ν²)/E (b (H y − y²/2) + t y). The vertical displacement of every node against that, relative to
/// the largest.
double column_error(int ny, double b, double t) {
  const double E = 1000, nu = 0.3, H = 10;
  const json p = {{"name", "column"},
                  {"dimension", 2},
                  {"materials", {{{"name", "m"}, {"E", E}, {"nu", nu}}}},
                  {"bodies",
                   {{{"name", "c"},
                     {"material", "m"},
                     {"mesh", {{"type", "block"}, {"nx", 1}, {"ny", ny}, {"lx", 1.0}, {"ly", H}}},
                     {"node_sets", {{{"name", "pin"}, {"nearest", {0.0, 0.0}}}}}}}},
                  {"boundary_conditions",
                   {{{"type", "displacement"}, {"body", "c"}, {"set", "ymin"}, {"uy", 0.0}},
                    {{"type", "displacement"}, {"body", "c"}, {"set", "pin"}, {"ux", 0.0}},
                    {{"type", "body_force"}, {"body", "c"}, {"by", -b}},
                    {{"type", "traction"}, {"body", "c"}, {"surface", "ymax"}, {"tx", 0.0}, {"ty", -t}}}},
                  {"solver", {{"mode", "direct"}}}};
  const Project project = parse_project(p.dump(), "column.json");
  const Model model = build_model(project);
  const Results r = run_project(project, model);
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  const Mesh& mesh = model.bodies[0].mesh;
  double error = 0, largest = 0;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const double y = mesh.nodes[static_cast<size_t>(n)][1];
    const double exact = -(1 - nu * nu) / E * (b * (H * y - y * y / 2) + t * y);
    error = std::max(error, std::abs(r.bodies[0].displacement[2 * n + 1] - exact));
    largest = std::max(largest, std::abs(exact));
  }
  return error / largest;
}
}  // namespace

TEST(Loads, APlaneStrainColumnUnderATopTractionIsNodallyExactAndUnderItsWeightConverges) {
  // a uniform stress: exact on any mesh
  EXPECT_LT(column_error(8, 0.0, 5.0), 1e-12);
  // its weight: σyy linear in y makes the lateral contraction vary along the column, a shear the bilinear elements
  // and the rollers only approximate, the less the finer the column (the load's integral being exact)
  const double coarse = column_error(8, 2.0, 5.0), fine = column_error(32, 2.0, 5.0);
  EXPECT_LT(coarse, 1e-3);
  EXPECT_LT(fine, coarse / 4);  // measured 5.5e-4 on 8, 9.6e-5 on 32 elements
}

}  // namespace test_loads
