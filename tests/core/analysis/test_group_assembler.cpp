// The group assembler: r_g = f_ext − f_int(u_g) is the linear system's right-hand side at rest and vanishes at its
// solution, the subdomains' residuals add up to the body's, and only the listed groups are touched; with local groups
// set (petsc) a Newton assembly gives every group its residual and only the local ones their tangent. The layout's
// dof geometry gives a subdomain's dofs the body's rigid-mode rows (the same on both sides of the interface). The
// Newton kernel's elements on 2 or 3 threads give bit for bit the tangent, residual and trial state of 1 thread, and
// name the same inverted element. A tangent that follows the residual at the same iterate (taking the points the
// residual kept) is the tangent assembled alone, bit for bit, and not once the state was committed in between.
#include <gtest/gtest.h>

#include "../../common/SaturatingSteel.h"

#include <Eigen/SparseCholesky>

#include "../partition/PartitionFixtures.h"
#include "analysis/GroupLayout.h"
#include "partition/StructuredPartition.h"

namespace test_group_assembler {

using namespace rollsim;

namespace {
/// A clamped block with a prescribed displacement and a force: both kinds of load in the residual.
Model loaded_block(int dim) {
  Model m = test::block_model(dim, {6, 3, 2});
  const double lz = dim == 3 ? 2 : 0;
  test::support(m, test::nodes_in_box(m, {0, 0, 0}, {0, 3, lz}));
  test::support(m, test::nodes_in_box(m, {6, 0, 0}, {6, 3, lz}), 1, -0.1);
  NodalForce force;
  force.nodes = test::nodes_in_box(m, {3, 3, 0}, {3, 3, lz});
  force.value = {2.0, -1.0, 0.5};
  m.forces.push_back(force);
  m.bodies[0].partition = structured_partition(m.bodies[0].mesh, {3, 1, 1});
  return m;
}
}  // namespace

TEST(GroupAssembler, ResidualVanishesAtTheSolution) {
  for (int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const Model m = loaded_block(dim);
    GroupLayout layout(m, false, Multipliers::NonRedundant);
    BlockSystem& sys = layout.system();
    layout.assemble(all_groups(sys), {}, 1.0);
    const Group rest = sys.groups[0];
    ASSERT_GT(rest.f.norm(), 0.0);
    const Eigen::VectorXd u = Eigen::SimplicialLDLT<SparseMatrix>(rest.K).solve(rest.f);
    layout.assemble({0}, {u}, 1.0);
    EXPECT_LE(sys.groups[0].f.norm(), 1e-10 * rest.f.norm());
    EXPECT_EQ((sys.groups[0].K - rest.K).norm(), 0.0) << "a linear material's tangent does not depend on u";
    layout.assemble({0}, {}, 0.25);  // at rest, a quarter of the load: a quarter of the residual
    EXPECT_LE((sys.groups[0].f - 0.25 * rest.f).norm(), 1e-14 * rest.f.norm());
  }
}

TEST(GroupAssembler, SubdomainResidualsAddUpToTheBody) {
  for (int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const Model m = loaded_block(dim);
    GroupLayout whole(m, false, Multipliers::NonRedundant), torn(m, true, Multipliers::NonRedundant);
    whole.assemble(all_groups(whole.system()), {}, 1.0);
    torn.assemble(all_groups(torn.system()), {}, 1.0);
    ASSERT_EQ(torn.system().groups.size(), 3u);
    // Σ_i L_i f_i over the body's free dofs: the subdomains' copies gathered by summing (not averaging)
    const BodyDecomposition dec = decompose_body(m, 0, m.bodies[0].partition);
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(whole.system().groups[0].f.size());
    for (size_t s = 0; s < dec.subdomains.size(); ++s)
      for (size_t l = 0; l < dec.subdomains[s].free_dofs.size(); ++l)
        sum[dec.subdomains[s].free_dofs[l]] += torn.system().groups[s].f[static_cast<Eigen::Index>(l)];
    EXPECT_LE((sum - whole.system().groups[0].f).norm(), 1e-12 * sum.norm());
  }
}

TEST(GroupAssembler, TouchesOnlyTheListedGroups) {
  const Model m = loaded_block(2);
  GroupLayout torn(m, true, Multipliers::NonRedundant);
  BlockSystem& sys = torn.system();
  torn.assemble({1}, {}, 1.0);
  EXPECT_EQ(sys.groups[0].K.nonZeros(), 0);
  EXPECT_GT(sys.groups[1].K.nonZeros(), 0);
  EXPECT_EQ(sys.groups[2].f.size(), 0);
  EXPECT_EQ(sys.groups[1].f.size(), sys.groups[1].K.rows());
}

TEST(GroupAssembler, NewtonTangentsOnlyOfTheLocalGroups) {
  const Model m = loaded_block(2);
  GroupLayout torn(m, true, Multipliers::NonRedundant);
  BlockSystem& sys = torn.system();
  torn.assembler().set_local({1});
  std::vector<Eigen::VectorXd> u;
  for (const Group& g : sys.groups) u.push_back(Eigen::VectorXd::Zero(g.C.cols()));
  const std::vector<size_t> all = all_groups(sys);
  EXPECT_FALSE(torn.assembler().assemble_newton(all, all, u, {1.0, 1.0, 0.0}, sys));
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    EXPECT_EQ(sys.groups[g].f.size(), sys.groups[g].C.cols()) << "every group's residual, group " << g;
    EXPECT_EQ(sys.groups[g].K.nonZeros() > 0, g == 1) << "the tangent of the local group only, group " << g;
    EXPECT_EQ(torn.assembler().tangent_evaluations()[g], 1) << "counted for the run, group " << g;
  }
}

TEST(GroupAssembler, SubdomainGeometryHasTheBodysRigidModeRows) {
  const Model m = loaded_block(3);
  GroupLayout whole(m, false, Multipliers::NonRedundant), torn(m, true, Multipliers::NonRedundant);
  const Eigen::MatrixXd& body = whole.system().groups[0].geometry.modes;
  ASSERT_EQ(body.cols(), 6);
  const BodyDecomposition dec = decompose_body(m, 0, m.bodies[0].partition);
  for (size_t s = 0; s < dec.subdomains.size(); ++s) {
    const Eigen::MatrixXd& modes = torn.system().groups[s].geometry.modes;
    ASSERT_EQ(modes.rows(), static_cast<long>(dec.subdomains[s].free_dofs.size()));
    for (size_t l = 0; l < dec.subdomains[s].free_dofs.size(); ++l)
      EXPECT_LT((modes.row(static_cast<long>(l)) - body.row(dec.subdomains[s].free_dofs[l])).norm(), 1e-14)
          << "subdomain " << s << ", local dof " << l;
  }
}

namespace {
/// A finite-strain J2 block of 12 × 8 × 6 elements (more than one chunk of the threaded kernel) stretched 2 % along x
/// and sheared, so that its points yield; assembled at u on `threads` threads.
struct Plastic {
  Model m = test::block_model(3, {12, 8, 6});
  Plastic() {
    m.bodies[0].material = rollsim::testing::saturating_steel();
    m.bodies[0].kinematics = Kinematics::Finite;
    m.bodies[0].formulation = Formulation::BBar;
    test::support(m, test::nodes_in_box(m, {0, 0, 0}, {0, 8, 6}));
  }
  /// u: x-stretch plus a shear wave (every free dof moves); `fold` pushes one corner node through its element.
  std::vector<Eigen::VectorXd> displacement(const GroupLayout& layout, bool fold) const {
    const Mesh& mesh = m.bodies[0].mesh;
    Eigen::VectorXd all(3 * mesh.num_nodes());
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const auto& x = mesh.nodes[n];
      all.segment<3>(3 * n) << 0.02 * x[0], 0.01 * x[0] * std::sin(x[2]), 0.005 * x[1];
    }
    if (fold) all.segment<3>(3 * (mesh.num_nodes() - 1)) << -3.0, -3.0, -3.0;
    return {layout.body_dofs()[0]->restrict_to_free(all)};
  }
  struct Out {
    InvertedElement bad;
    Group group;
    std::vector<double> trial;
  };
  Out assemble(int threads, bool fold = false) const {
    GroupLayout layout(m, false, Multipliers::NonRedundant);
    BlockSystem& sys = layout.system();
    layout.assembler().set_threads(threads);
    const std::vector<size_t> all = all_groups(sys);
    Out out;
    out.bad = layout.assembler().assemble_newton(all, all, displacement(layout, fold), {1.0, 1.0, 0.0}, sys);
    out.group = sys.groups[0];
    layout.assembler().commit();
    out.trial = layout.assembler().committed_state(0, m.bodies[0].mesh.num_elements());
    return out;
  }
};

bool same_bits(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::VectorXd>& b) {
  return a.size() == b.size() && std::equal(a.data(), a.data() + a.size(), b.data());
}
}  // namespace

TEST(GroupAssembler, NewtonElementsOnThreadsGiveTheOneThreadResultBitForBit) {
  const Plastic block;
  const Plastic::Out one = block.assemble(1);
  ASSERT_FALSE(one.bad);
  ASSERT_GT(*std::max_element(one.trial.begin(), one.trial.end()), 0.0) << "points yield";
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    const Plastic::Out many = block.assemble(threads);
    ASSERT_FALSE(many.bad);
    EXPECT_TRUE(same_bits(many.group.f, one.group.f));
    ASSERT_EQ(many.group.K.nonZeros(), one.group.K.nonZeros());
    EXPECT_TRUE(
        std::equal(one.group.K.valuePtr(), one.group.K.valuePtr() + one.group.K.nonZeros(), many.group.K.valuePtr()));
    EXPECT_EQ(many.trial, one.trial);
  }
}

// The selective update's two passes: every group's residual, then the tangent of those it refactors at the same
// iterate (the second taking the first's point updates: FiniteStrainElement::PointUpdates).
TEST(GroupAssembler, ATangentAfterTheResidualAtTheSameIterateIsTheTangentAloneBitForBit) {
  const Plastic block;
  const Plastic::Out alone = block.assemble(1);
  GroupLayout layout(block.m, false, Multipliers::NonRedundant);
  BlockSystem& sys = layout.system();
  const std::vector<size_t> all = all_groups(sys);
  const std::vector<Eigen::VectorXd> u = block.displacement(layout, false);
  ASSERT_FALSE(layout.assembler().assemble_newton(all, {}, u, {1.0, 1.0, 0.0}, sys));
  ASSERT_FALSE(layout.assembler().assemble_newton(all, all, u, {1.0, 1.0, 0.0}, sys));
  EXPECT_TRUE(same_bits(sys.groups[0].f, alone.group.f));
  ASSERT_EQ(sys.groups[0].K.nonZeros(), alone.group.K.nonZeros());
  EXPECT_TRUE(std::equal(alone.group.K.valuePtr(), alone.group.K.valuePtr() + alone.group.K.nonZeros(),
                         sys.groups[0].K.valuePtr()));
  layout.assembler().commit();
  EXPECT_EQ(layout.assembler().committed_state(0, block.m.bodies[0].mesh.num_elements()), alone.trial);
}

// A commit between the residual and the tangent at the same iterate: the tangent is that of the new state, not of
// the points kept before it (the flow committed, the same strain is an elastic step: its modulus is the elastic one).
TEST(GroupAssembler, ATangentAfterACommitIsThatOfTheCommittedState) {
  const Plastic block;
  const int elements = block.m.bodies[0].mesh.num_elements();
  GroupLayout layout(block.m, false, Multipliers::NonRedundant);
  BlockSystem& sys = layout.system();
  const std::vector<size_t> all = all_groups(sys);
  const std::vector<Eigen::VectorXd> u = block.displacement(layout, false);
  ASSERT_FALSE(layout.assembler().assemble_newton(all, all, u, {1.0, 1.0, 0.0}, sys));
  const SparseMatrix before = sys.groups[0].K;
  ASSERT_FALSE(layout.assembler().assemble_newton(all, {}, u, {1.0, 1.0, 0.0}, sys));
  layout.assembler().commit();
  ASSERT_FALSE(layout.assembler().assemble_newton(all, all, u, {1.0, 1.0, 0.0}, sys));
  // the same from a layout given that committed state
  GroupLayout fresh(block.m, false, Multipliers::NonRedundant);
  fresh.assembler().set_committed_state(0, layout.assembler().committed_state(0, elements));
  ASSERT_FALSE(fresh.assembler().assemble_newton(all, all, u, {1.0, 1.0, 0.0}, fresh.system()));
  const SparseMatrix& expected = fresh.system().groups[0].K;
  EXPECT_GT((expected - before).norm(), 1e-3 * before.norm()) << "the committed flow changes the tangent";
  ASSERT_EQ(sys.groups[0].K.nonZeros(), expected.nonZeros());
  EXPECT_TRUE(std::equal(expected.valuePtr(), expected.valuePtr() + expected.nonZeros(), sys.groups[0].K.valuePtr()));
  EXPECT_TRUE(same_bits(sys.groups[0].f, fresh.system().groups[0].f));
}

TEST(GroupAssembler, NewtonElementsOnThreadsNameTheSameInvertedElement) {
  const Plastic block;
  const Plastic::Out one = block.assemble(1, true), two = block.assemble(2, true);
  ASSERT_TRUE(one.bad);
  EXPECT_EQ(two.bad.group, one.bad.group);
  EXPECT_EQ(two.bad.element, one.bad.element);
}

}  // namespace test_group_assembler
