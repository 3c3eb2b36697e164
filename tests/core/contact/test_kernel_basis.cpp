// Rigid-mode detection (kernel_basis): the number of free modes for bodies held at nothing, one node, one
// component, two nodes, an edge or a face, in 2D (0..3) and 3D (0..6), and K R = 0 to round-off.
#include <gtest/gtest.h>

#include "../../common/FiniteBlock.h"
#include "fem/Assembler.h"
#include "mesh/StructuredBlock.h"
#include "model/DofMap.h"
#include "model/RigidModes.h"

namespace test_kernel_basis {

using namespace rollsim;

namespace {
struct Support {
  std::vector<int> nodes;
  std::array<std::optional<double>, 3> value;
};

/// Free rigid modes of a unit block with the given supports; checks K R = 0 on the way.
long free_modes(int dim, const std::vector<Support>& supports) {
  BlockSpec spec;
  spec.dim = dim;
  spec.n = dim == 2 ? std::array<int, 3>{3, 2, 1} : std::array<int, 3>{2, 2, 2};  // 3 nodes on the first line
  Body body;
  body.mesh = make_block(spec);
  body.material = {1000.0, 0.3};
  std::vector<DisplacementBC> bcs;
  for (const Support& s : supports) bcs.push_back({0, "s", s.nodes, s.value});
  const DofMap dofs(body, 0, bcs);
  const Eigen::MatrixXd R = kernel_basis(body.mesh, dofs);
  SparseMatrix K;
  Eigen::VectorXd f;
  Assembler(body, dofs).assemble(K, f);
  if (R.cols()) {
    EXPECT_LT((K * R).cwiseAbs().maxCoeff(), 1e-10 * K.coeffs().cwiseAbs().maxCoeff());
    EXPECT_LT((R.transpose() * R - Eigen::MatrixXd::Identity(R.cols(), R.cols())).norm(), 1e-12);
  }
  return R.cols();
}
const std::optional<double> kFix = 0.0, kFree;
}  // namespace

TEST(KernelBasis, TwoDimensionalModesZeroToThree) {
  EXPECT_EQ(free_modes(2, {}), 3);
  EXPECT_EQ(free_modes(2, {{{0}, {kFree, kFix, kFree}}}), 2);  // one node held in y
  EXPECT_EQ(free_modes(2, {{{0}, {kFix, kFix, kFree}}}), 1);   // one node pinned: rotation left
  EXPECT_EQ(free_modes(2, {{{0}, {kFix, kFix, kFree}}, {{3}, {kFree, kFix, kFree}}}), 0);  // pin + roller
  EXPECT_EQ(free_modes(2, {{{0, 1, 2, 3}, {kFree, kFix, kFree}}}), 1);  // a line held in y: x translation left
}

TEST(KernelBasis, ThreeDimensionalModesZeroToSix) {
  EXPECT_EQ(free_modes(3, {}), 6);
  EXPECT_EQ(free_modes(3, {{{0}, {kFix, kFix, kFix}}}), 3);                             // a point: rotations left
  EXPECT_EQ(free_modes(3, {{{0}, {kFix, kFix, kFix}}, {{3}, {kFix, kFix, kFix}}}), 1);  // an axis: 1 rotation
  EXPECT_EQ(free_modes(3, {{{0, 1, 2, 3}, {kFree, kFree, kFix}}}), 3);                  // an edge line held in z
  EXPECT_EQ(free_modes(3, {{{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, {kFix, kFix, kFix}}}), 0);  // a face clamped
}

// rigid_mode_rows at any list of dofs in a mesh's frame gives rigid_modes' rows there (the one formula), and K of an
// unsupported body annihilates them.
TEST(KernelBasis, ModeRowsAtChosenDofsAreTheBodysModes) {
  for (int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    BlockSpec spec;
    spec.dim = dim;
    spec.n = {3, 2, 2};
    const Mesh mesh = make_block(spec);
    const Eigen::MatrixXd R = rigid_modes(mesh);
    const std::vector<int> dofs = {1, 4, 7, dim * mesh.num_nodes() - 1};  // a few, in any component
    Eigen::MatrixXd x(static_cast<long>(dofs.size()), dim);
    Eigen::VectorXi component(static_cast<long>(dofs.size()));
    for (size_t i = 0; i < dofs.size(); ++i) {
      for (int k = 0; k < dim; ++k) x(static_cast<long>(i), k) = mesh.nodes[dofs[i] / dim][k];
      component[static_cast<long>(i)] = dofs[i] % dim;
    }
    const Eigen::MatrixXd rows = rigid_mode_rows(x, component, mode_frame(mesh));
    ASSERT_EQ(rows.cols(), R.cols());
    for (size_t i = 0; i < dofs.size(); ++i)
      EXPECT_LT((rows.row(static_cast<long>(i)) - R.row(dofs[i])).norm(), 1e-15) << "dof " << dofs[i];
  }
}

// stiffness_kernel: of a floating block's finite-strain tangent, all six geometric modes while it is unstressed,
// the three translations once it is stretched (its rotations turn the internal forces: K R_rot ≠ 0).
TEST(KernelBasis, AStressedFiniteStrainTangentKeepsOnlyTheTranslations) {
  const Body body = testing_support::finite_block(3, {2, 2, 2});
  const DofMap dofs(body, 0, {});
  const Assembler assembler(body, dofs);
  auto kernel_at = [&](double stretch) {
    Eigen::VectorXd u(body.mesh.num_nodes() * 3);
    for (int n = 0; n < body.mesh.num_nodes(); ++n)
      for (int c = 0; c < 3; ++c) u[n * 3 + c] = stretch * (c + 1) * body.mesh.nodes[n][c];  // unequal stretches
    IntegrationState state = IntegrationState::initial(body);
    SparseMatrix K;
    Eigen::VectorXd f;
    EXPECT_LT(assembler.assemble(u, &K, f, state), 0);
    const Eigen::MatrixXd R = stiffness_kernel(K, kernel_basis(body.mesh, dofs, &u));
    EXPECT_LT((K * R).cwiseAbs().maxCoeff(), 1e-10 * K.coeffs().cwiseAbs().maxCoeff());
    EXPECT_LT((R.transpose() * R - Eigen::MatrixXd::Identity(R.cols(), R.cols())).norm(), 1e-12);
    return R;
  };
  EXPECT_EQ(kernel_at(0.0).cols(), 6);
  const Eigen::MatrixXd R = kernel_at(0.05);
  ASSERT_EQ(R.cols(), 3);
  for (int c = 0; c < 3; ++c) {  // each translation lies in span R
    Eigen::VectorXd t = Eigen::VectorXd::Zero(R.rows());
    for (Eigen::Index i = c; i < t.size(); i += 3) t[i] = 1.0;
    EXPECT_LT((t - R * (R.transpose() * t)).norm(), 1e-10 * t.norm()) << "translation " << c;
  }
}

}  // namespace test_kernel_basis
