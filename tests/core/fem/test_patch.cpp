// Patch tests: on distorted meshes, a linear displacement field imposed on the boundary is
// reproduced inside and gives constant stress, to round-off (Q4 and H8, full and B-bar).
#include <gtest/gtest.h>

#include <random>

#include "analysis/LinearStatic.h"
#include "material/LinearElastic.h"
#include "mesh/StructuredBlock.h"
#include "solve/SolverStrategy.h"

namespace test_patch {

using namespace rollsim;

namespace {

bool on_boundary(const std::array<double, 3>& x, int dim) {
  for (int k = 0; k < dim; ++k)
    if (std::abs(x[k]) < 1e-12 || std::abs(x[k] - 1.0) < 1e-12) return true;
  return false;
}

// Linear field u_i = sum_j G_ij x_j + c_i
const double G[3][3] = {{1e-3, 2e-3, -1e-3}, {-3e-3, 0.5e-3, 2e-3}, {1.5e-3, -1e-3, 2.5e-3}};
double field(const std::array<double, 3>& x, int i) {
  return G[i][0] * x[0] + G[i][1] * x[1] + G[i][2] * x[2] + 0.01 * i;
}

Model distorted_patch(int dim, Formulation f) {
  Model m;
  m.dim = dim;
  BlockSpec spec;
  spec.dim = dim;
  spec.n = {3, 3, 3};
  Body b;
  b.name = "patch";
  b.mesh = make_block(spec);
  b.material = {1000.0, 0.3};
  b.formulation = f;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.09, 0.09);
  for (auto& x : b.mesh.nodes)
    if (!on_boundary(x, dim))
      for (int k = 0; k < dim; ++k) x[k] += jitter(rng);
  std::vector<int> boundary;
  for (int n = 0; n < b.mesh.num_nodes(); ++n)
    if (on_boundary(b.mesh.nodes[n], dim)) boundary.push_back(n);
  for (int n : boundary) {
    DisplacementBC bc{0, "boundary", {n}, {}};
    for (int c = 0; c < dim; ++c) bc.value[c] = field(b.mesh.nodes[n], c);
    m.displacements.push_back(bc);
  }
  m.bodies.push_back(std::move(b));
  return m;
}

void check_patch(int dim, Formulation f) {
  const Model m = distorted_patch(dim, f);
  check_element_orientation(m.bodies[0].mesh);
  auto solver = make_solver("direct", {});
  const Results r = run_linear_static(m, *solver);
  const Mesh& mesh = m.bodies[0].mesh;
  for (int n = 0; n < mesh.num_nodes(); ++n)
    for (int c = 0; c < dim; ++c) EXPECT_NEAR(r.bodies[0].displacement[n * dim + c], field(mesh.nodes[n], c), 1e-13);
  // constant stress: sigma = lambda tr(eps) I + 2 mu eps
  const LinearElastic mat(m.bodies[0].material.E, m.bodies[0].material.nu);
  double eps[3][3], tr = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) eps[i][j] = (i < dim && j < dim) ? 0.5 * (G[i][j] + G[j][i]) : 0.0;
  for (int i = 0; i < 3; ++i) tr += eps[i][i];
  const int idx[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
  for (const auto& s : r.bodies[0].element_stress)
    for (int c = 0; c < 6; ++c) {
      const double expected = 2 * mat.mu() * eps[idx[c][0]][idx[c][1]] + (c < 3 ? mat.lambda() * tr : 0.0);
      EXPECT_NEAR(s[c], expected, 1e-10) << "component " << c;
    }
  for (const auto& s : r.bodies[0].nodal_stress) EXPECT_NEAR(s[0], r.bodies[0].element_stress[0][0], 1e-10);
}

}  // namespace

TEST(PatchTest, Quad4FullIntegration) { check_patch(2, Formulation::Full); }
TEST(PatchTest, Quad4BBar) { check_patch(2, Formulation::BBar); }
TEST(PatchTest, Hex8FullIntegration) { check_patch(3, Formulation::Full); }
TEST(PatchTest, Hex8BBar) { check_patch(3, Formulation::BBar); }

}  // namespace test_patch
