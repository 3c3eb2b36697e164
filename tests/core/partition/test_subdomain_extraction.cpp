// Subdomain extraction: local stiffnesses and loads add up (through the Boolean maps) to the body's, and the
// kernels R_s of floating subdomains are exact — including the near-singular supports (0 nodes, 1 node, a line,
// a face of the Dirichlet boundary).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "PartitionFixtures.h"
#include "fem/Assembler.h"
#include "fem/Loads.h"
#include "partition/MetisPartition.h"
#include "partition/StructuredPartition.h"

namespace test_subdomain_extraction {

using namespace rollsim;

namespace {
/// A cantilever with a clamped end, a prescribed tip displacement, a point force and all the machinery.
Model cantilever(int dim, std::array<int, 3> n) {
  Model m = test::block_model(dim, n);
  const double lx = n[0], ly = n[1], lz = dim == 3 ? n[2] : 0;
  test::support(m, test::nodes_in_box(m, {0, 0, 0}, {0, ly, lz}));
  test::support(m, test::nodes_in_box(m, {lx, 0, lz}, {lx, ly, lz}), dim - 1, 0.25);
  NodalForce force;
  force.nodes = test::nodes_in_box(m, {lx / 2, 0, 0}, {lx / 2, ly, lz});
  force.value = {1.0, -2.0, 0.5};
  m.forces.push_back(force);
  return m;
}

struct BodyOperator {
  SparseMatrix K;
  Eigen::VectorXd f;
};

BodyOperator undivided(const Model& m) {
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  BodyOperator op;
  Assembler(m.bodies[0], dofs).assemble(op.K, op.f);
  op.f += dofs.restrict_to_free(external_nodal_load(m, 0));
  return op;
}

void expect_sums_to_body(const Model& m, const Partition& p) {
  const BodyOperator body = undivided(m);
  const BodyDecomposition dec = decompose_body(m, 0, p);
  SparseMatrix K(body.K.rows(), body.K.cols());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(body.f.size());
  for (size_t s = 0; s < dec.groups.size(); ++s) {
    const SparseMatrix L = test::local_to_body(dec.subdomains[s], dec.body_free_dofs);
    K += SparseMatrix(L * dec.groups[s].K * SparseMatrix(L.transpose()));
    f += L * dec.groups[s].f;
  }
  EXPECT_LE((K - body.K).norm(), 1e-14 * body.K.norm()) << p.description;
  EXPECT_LE((f - body.f).norm(), 1e-14 * body.f.norm()) << p.description;
}

void expect_kernels_exact(const BodyDecomposition& dec) {
  for (const Group& g : dec.groups) {
    if (g.R.cols() == 0) continue;
    const Eigen::MatrixXd KR = g.K * g.R;
    EXPECT_LE(KR.norm(), 1e-12 * g.K.norm()) << g.name;
    EXPECT_LE((g.R.transpose() * g.R - Eigen::MatrixXd::Identity(g.R.cols(), g.R.cols())).norm(), 1e-12);
  }
}

/// Rigid modes per subdomain, checked against the spectrum of each (small) K_s: exactly R.cols() eigenvalues
/// vanish, and the next one is clearly non-zero.
std::vector<int> checked_modes(const Model& m, const std::array<int, 3>& slices) {
  const BodyDecomposition dec = decompose_body(m, 0, structured_partition(m.bodies[0].mesh, slices));
  expect_kernels_exact(dec);
  for (const Group& g : dec.groups) {
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(g.K)).eigenvalues();
    const double scale = ev.maxCoeff();
    const Eigen::Index r = g.R.cols();
    for (Eigen::Index k = 0; k < r; ++k) EXPECT_LE(std::abs(ev[k]), 1e-10 * scale) << g.name;
    EXPECT_GT(ev[r], 1e-6 * scale) << g.name << ": K_s has more zero eigenvalues than rigid modes found";
  }
  return test::modes_per_group(dec);
}
}  // namespace

TEST(SubdomainExtraction, LocalNumberingFollowsTheBody) {
  const Model m = cantilever(2, {8, 4, 1});
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  const auto subs = extract_subdomains(m.bodies[0], dofs, structured_partition(m.bodies[0].mesh, {2, 2, 1}));
  ASSERT_EQ(subs.size(), 4u);
  for (const Subdomain& s : subs) {
    EXPECT_EQ(s.body.mesh.num_elements(), 8);
    EXPECT_EQ(s.body.mesh.num_nodes(), 15);
    EXPECT_TRUE(std::is_sorted(s.free_dofs.begin(), s.free_dofs.end()));
    for (int l = 0; l < s.body.mesh.num_nodes(); ++l)
      for (int c = 0; c < 2; ++c) {
        const int eq = s.dofs->equation(l, c), body_eq = dofs.equation(s.nodes[l], c);
        EXPECT_EQ(eq < 0, body_eq < 0);
        if (eq >= 0) EXPECT_EQ(s.free_dofs[eq], body_eq);
        if (eq < 0) EXPECT_EQ(s.dofs->prescribed(l, c), dofs.prescribed(s.nodes[l], c));
        EXPECT_EQ(s.body.mesh.nodes[l], m.bodies[0].mesh.nodes[s.nodes[l]]);
      }
  }
}

TEST(SubdomainExtraction, StiffnessesAndLoadsSumToTheBody) {
  const Model m2 = cantilever(2, {12, 6, 1});
  expect_sums_to_body(m2, structured_partition(m2.bodies[0].mesh, {3, 2, 1}));
  expect_sums_to_body(m2, metis_partition(m2.bodies[0].mesh, 5));
  const Model m3 = cantilever(3, {6, 4, 4});
  expect_sums_to_body(m3, structured_partition(m3.bodies[0].mesh, {2, 2, 2}));
  expect_sums_to_body(m3, metis_partition(m3.bodies[0].mesh, 3));
}

TEST(SubdomainExtraction, FloatingKernelsAreExact) {
  const Model m2 = cantilever(2, {24, 12, 1});
  expect_kernels_exact(decompose_body(m2, 0, structured_partition(m2.bodies[0].mesh, {4, 3, 1})));
  expect_kernels_exact(decompose_body(m2, 0, metis_partition(m2.bodies[0].mesh, 7)));
  const Model m3 = cantilever(3, {8, 4, 4});
  expect_kernels_exact(decompose_body(m3, 0, structured_partition(m3.bodies[0].mesh, {4, 2, 2})));
  const Model plate = test::sample_model("plate-hole-2d");
  expect_kernels_exact(decompose_body(plate, 0, metis_partition(plate.bodies[0].mesh, 6)));
}

TEST(SubdomainExtraction, KernelDimensionNear2DSupports) {
  // 4×4 block in 2×2 subdomains (ids: 0 lower left, 1 lower right, 2 upper left, 3 upper right)
  Model none = test::block_model(2, {4, 4, 1});
  test::support(none, test::nodes_in_box(none, {4, 4, 0}, {4, 4, 0}), 1);  // held elsewhere: a corner of 3
  EXPECT_EQ(checked_modes(none, {2, 2, 1}), (std::vector<int>{3, 3, 3, 2}));
  Model node = test::block_model(2, {4, 4, 1});
  test::support(node, test::nodes_in_box(node, {0, 0, 0}, {0, 0, 0}));  // 1 node, both components
  EXPECT_EQ(checked_modes(node, {2, 2, 1}), (std::vector<int>{1, 3, 3, 3}));
  Model edge = test::block_model(2, {4, 4, 1});
  test::support(edge, test::nodes_in_box(edge, {0, 0, 0}, {0, 2, 0}));  // an edge of 0; node (0, 2) of 2
  EXPECT_EQ(checked_modes(edge, {2, 2, 1}), (std::vector<int>{0, 3, 1, 3}));
  Model roller = test::block_model(2, {4, 4, 1});
  test::support(roller, test::nodes_in_box(roller, {0, 0, 0}, {4, 0, 0}), 1);  // uy = 0 along y = 0
  EXPECT_EQ(checked_modes(roller, {2, 2, 1}), (std::vector<int>{1, 1, 3, 3}));
}

TEST(SubdomainExtraction, SlenderSubdomainNeedsNoRankTolerance) {
  // A 96 × 1 strip held at one node: 1 rigid mode (rotation about the node). Its softest bending mode has an
  // eigenvalue far below any tolerance a numerical rank decision would dare to use, yet the geometric kernel
  // needs none: exactly 1 mode, K R = 0 to round-off, and the next eigenvalue is tiny but not zero.
  Model strip = test::block_model(2, {96, 1, 1});
  test::support(strip, test::nodes_in_box(strip, {0, 0, 0}, {0, 0, 0}));
  const BodyDecomposition dec = decompose_body(strip, 0, structured_partition(strip.bodies[0].mesh, {1, 1, 1}));
  const Group& g = dec.groups[0];
  ASSERT_EQ(g.R.cols(), 1);
  EXPECT_LE(Eigen::MatrixXd(g.K * g.R).norm(), 1e-12 * g.K.norm());
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(g.K)).eigenvalues();
  EXPECT_LE(std::abs(ev[0]), 1e-13 * ev.maxCoeff());
  EXPECT_LT(ev[1], 1e-6 * ev.maxCoeff());   // a 1e-6 relative rank test would call the bending mode rigid
  EXPECT_GT(ev[1], 1e-10 * ev.maxCoeff());  // but it is not
}

TEST(SubdomainExtraction, KernelDimensionNear3DSupports) {
  // 4×4×4 block in 2×2×2 subdomains, id = ix + 2 iy + 4 iz
  Model none = test::block_model(3, {4, 4, 4});
  test::support(none, test::nodes_in_box(none, {0, 0, 0}, {0, 0, 0}));  // 1 node of subdomain 0 only
  EXPECT_EQ(checked_modes(none, {2, 2, 2}), (std::vector<int>{3, 6, 6, 6, 6, 6, 6, 6}));
  Model line = test::block_model(3, {4, 4, 4});
  test::support(line, test::nodes_in_box(line, {0, 0, 0}, {0, 4, 0}));  // a line of subdomains 0 and 2
  EXPECT_EQ(checked_modes(line, {2, 2, 2}), (std::vector<int>{1, 6, 1, 6, 6, 6, 6, 6}));
  Model face = test::block_model(3, {4, 4, 4});
  test::support(face, test::nodes_in_box(face, {0, 0, 0}, {0, 2, 2}));  // a face of 0; lines of 2 and 4; a node of 6
  EXPECT_EQ(checked_modes(face, {2, 2, 2}), (std::vector<int>{0, 6, 1, 6, 1, 6, 3, 6}));
  Model tip = test::block_model(3, {4, 4, 4});
  test::support(tip, test::nodes_in_box(tip, {0, 0, 0}, {0, 4, 4}));
  test::support(tip, test::nodes_in_box(tip, {4, 0, 4}, {4, 4, 4}), 2, 1.0);  // uz on an edge line: 4 modes left
  EXPECT_EQ(checked_modes(tip, {2, 2, 2}), (std::vector<int>{0, 6, 0, 6, 0, 4, 0, 4}));
}

}  // namespace test_subdomain_extraction
