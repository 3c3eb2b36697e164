// The BlockSystem part of a decomposed body: signed Boolean rows, the multiplier choices, the glued system
// reproducing the undivided body, mapping back, and joining with other groups' constraints.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "../partition/PartitionFixtures.h"
#include "fem/Assembler.h"
#include "fem/Loads.h"
#include "partition/MetisPartition.h"
#include "partition/StructuredPartition.h"

namespace test_subdomain_decomposition {

using namespace rollsim;

namespace {
Model clamped(int dim, std::array<int, 3> n) {
  Model m = test::block_model(dim, n);
  const double lz = dim == 3 ? n[2] : 0;
  test::support(m, test::nodes_in_box(m, {0, 0, 0}, {0, double(n[1]), lz}));
  test::support(m, test::nodes_in_box(m, {double(n[0]), 0, lz}, {double(n[0]), double(n[1]), lz}), dim - 1, -0.5);
  NodalForce force;
  force.nodes = test::nodes_in_box(m, {double(n[0]) / 2, 0, 0}, {double(n[0]) / 2, double(n[1]), lz});
  force.value = {3.0, 1.0, -1.0};
  m.forces.push_back(force);
  return m;
}

Eigen::VectorXd body_solution(const Model& m) {
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  SparseMatrix K;
  Eigen::VectorXd f;
  Assembler(m.bodies[0], dofs).assemble(K, f);
  f += dofs.restrict_to_free(external_nodal_load(m, 0));
  return Eigen::SimplicialLDLT<SparseMatrix>(K).solve(f);
}

/// Solves [diag K_s, Bᵀ; B, 0] [u; λ] = [f; d] densely (least squares: redundant B leaves λ non-unique).
std::vector<Eigen::VectorXd> glued_solution(const BodyDecomposition& dec) {
  Eigen::Index n = 0;
  for (const Group& g : dec.groups) n += g.K.rows();
  const Eigen::Index m = dec.d.size();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + m, n + m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
  Eigen::Index at = 0;
  for (const Group& g : dec.groups) {
    const Eigen::Index k = g.K.rows();
    A.block(at, at, k, k) = Eigen::MatrixXd(g.K);
    A.block(n, at, m, k) = Eigen::MatrixXd(g.C);
    A.block(at, n, k, m) = Eigen::MatrixXd(g.C).transpose();
    rhs.segment(at, k) = g.f;
    at += k;
  }
  rhs.tail(m) = dec.d;
  const Eigen::VectorXd x = A.completeOrthogonalDecomposition().solve(rhs);
  std::vector<Eigen::VectorXd> u;
  at = 0;
  for (const Group& g : dec.groups) {
    u.push_back(x.segment(at, g.K.rows()));
    at += g.K.rows();
  }
  return u;
}

Eigen::MatrixXd stacked_B(const BodyDecomposition& dec) {
  Eigen::MatrixXd B(dec.d.size(), 0);
  for (const Group& g : dec.groups) {
    Eigen::MatrixXd wider(B.rows(), B.cols() + g.C.cols());
    wider << B, Eigen::MatrixXd(g.C);
    B = wider;
  }
  return B;
}
}  // namespace

TEST(SubdomainDecomposition, SignedBooleanRows) {
  const Model m = clamped(2, {8, 4, 1});
  for (Multipliers choice : {Multipliers::NonRedundant, Multipliers::FullyRedundant, Multipliers::FacePairs}) {
    DecomposeOptions o;
    o.multipliers = choice;
    const BodyDecomposition dec = decompose_body(m, 0, structured_partition(m.bodies[0].mesh, {2, 2, 1}), o);
    const Eigen::MatrixXd B = stacked_B(dec);
    for (Eigen::Index r = 0; r < B.rows(); ++r) {  // paper §2: one +1 and one −1 per row, d = 0
      EXPECT_EQ((B.row(r).array() == 1.0).count(), 1);
      EXPECT_EQ((B.row(r).array() == -1.0).count(), 1);
      EXPECT_EQ((B.row(r).array() != 0.0).count(), 2);
    }
    EXPECT_EQ(dec.d, Eigen::VectorXd::Zero(B.rows()));
    const Eigen::Index rank = B.fullPivLu().rank();
    if (choice == Multipliers::NonRedundant) EXPECT_EQ(rank, B.rows()) << "non-redundant B has full row rank";
    // interface: 4 + 8 nodes on the cuts x = 4, y = 2 besides the crosspoint (4, 2) of four subdomains; (0, 2) is
    // clamped (no free dof) and (8, 2) has u_y prescribed (one free dof); the paper's count takes every dof
    const long crosspoint = choice == Multipliers::NonRedundant ? 3 : choice == Multipliers::FacePairs ? 4 : 6;
    EXPECT_EQ(dec.num_multipliers(), 2 * (4 + 8 - 2) + 1 + 2 * crosspoint) << to_string(choice);
    EXPECT_EQ(dec.paper_convention_multipliers, 2 * (4 + 8) + 2 * 3);
  }
}

TEST(SubdomainDecomposition, CornerOfEightSubdomains) {
  const Model m = test::block_model(3, {2, 2, 2});
  const Partition p = structured_partition(m.bodies[0].mesh, {2, 2, 2});
  const Interface iface = find_interface(m.bodies[0].mesh, p);
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  ASSERT_EQ(iface.nodes.size(), 19u);  // 3 planes of 9 nodes, 3 lines of 3 nodes, 1 centre
  for (const InterfaceNode& n : iface.nodes) {
    const size_t k = n.subdomains.size();
    EXPECT_EQ(constraint_pairs(n, Multipliers::NonRedundant).size(), k - 1);
    EXPECT_EQ(constraint_pairs(n, Multipliers::FullyRedundant).size(), k * (k - 1) / 2);
    EXPECT_EQ(constraint_pairs(n, Multipliers::FacePairs).size(), k == 8 ? 12u : k == 4 ? 4u : 1u);
  }
  EXPECT_EQ(count_multipliers(iface, dofs, Multipliers::NonRedundant), 3 * (12 * 1 + 6 * 3 + 7));
  EXPECT_EQ(count_multipliers(iface, dofs, Multipliers::FacePairs), 3 * (12 * 1 + 6 * 4 + 12));
  EXPECT_EQ(count_multipliers(iface, dofs, Multipliers::FullyRedundant), 3 * (12 * 1 + 6 * 6 + 28));
  EXPECT_EQ(paper_convention_count(iface, 3), 3 * (12 * 1 + 6 * 4 + 12));
}

TEST(SubdomainDecomposition, GluedSubdomainsReproduceTheBody) {
  for (int dim : {2, 3}) {
    const Model m = dim == 2 ? clamped(2, {8, 4, 1}) : clamped(3, {4, 2, 2});
    const Eigen::VectorXd u = body_solution(m);
    const std::array<int, 3> slices = dim == 2 ? std::array<int, 3>{2, 2, 1} : std::array<int, 3>{2, 1, 2};
    for (Multipliers choice : {Multipliers::NonRedundant, Multipliers::FullyRedundant, Multipliers::FacePairs}) {
      DecomposeOptions o;
      o.multipliers = choice;
      const BodyDecomposition dec = decompose_body(m, 0, structured_partition(m.bodies[0].mesh, slices), o);
      EXPECT_GT(dec.num_rigid_modes(), 0);
      const std::vector<Eigen::VectorXd> us = glued_solution(dec);
      for (InterfaceValue how : {InterfaceValue::Average, InterfaceValue::FirstCopy})
        EXPECT_LE((gather_free(dec, us, how) - u).norm(), 1e-9 * u.norm()) << dim << "D " << to_string(choice);
    }
  }
}

TEST(SubdomainDecomposition, MetisDecompositionReproducesTheBody) {
  const Model m = clamped(2, {10, 6, 1});
  const BodyDecomposition dec = decompose_body(m, 0, metis_partition(m.bodies[0].mesh, 4));
  const Eigen::VectorXd u = body_solution(m);
  EXPECT_LE((gather_free(dec, glued_solution(dec)) - u).norm(), 1e-9 * u.norm());
}

TEST(SubdomainDecomposition, GatherAveragesOrTakesTheFirstCopy) {
  const Model m = clamped(2, {4, 2, 1});
  const BodyDecomposition dec = decompose_body(m, 0, structured_partition(m.bodies[0].mesh, {2, 1, 1}));
  std::vector<Eigen::VectorXd> u;
  for (const Group& g : dec.groups) u.push_back(Eigen::VectorXd::Constant(g.K.rows(), double(u.size() + 1)));
  const Eigen::VectorXd avg = gather_free(dec, u), first = gather_free(dec, u, InterfaceValue::FirstCopy);
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  for (int n = 0; n < m.bodies[0].mesh.num_nodes(); ++n) {
    const double x = m.bodies[0].mesh.nodes[n][0];
    const int eq = dofs.equation(n, 0);
    if (eq < 0) continue;
    EXPECT_EQ(avg[eq], x < 2 ? 1.0 : x > 2 ? 2.0 : 1.5);
    EXPECT_EQ(first[eq], x <= 2 ? 1.0 : 2.0);
  }
}

TEST(SubdomainDecomposition, AppendsToASystemWithOtherConstraints) {
  const Model m = clamped(2, {4, 2, 1});
  BodyDecomposition dec = decompose_body(m, 0, structured_partition(m.bodies[0].mesh, {2, 1, 1}));
  const long mD = dec.num_multipliers();
  // a contact-like block on the undivided body: one row per free dof of the cut x = 2
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  std::vector<Eigen::Triplet<double, int>> t;
  int rows = 0;
  for (int n = 0; n < m.bodies[0].mesh.num_nodes(); ++n)
    if (m.bodies[0].mesh.nodes[n][0] == 2.0 && dofs.equation(n, 1) >= 0)
      t.emplace_back(rows++, dofs.equation(n, 1), 2.0);
  SparseMatrix C_body(rows, dofs.num_free());
  C_body.setFromTriplets(t.begin(), t.end());
  const std::vector<SparseMatrix> C = split_constraint_columns(C_body, dec);
  const Eigen::VectorXd probe = Eigen::VectorXd::LinSpaced(dofs.num_free(), 1.0, 2.0);
  Eigen::VectorXd Cu = Eigen::VectorXd::Zero(rows);
  for (size_t s = 0; s < C.size(); ++s)
    Cu += C[s] * SparseMatrix(test::local_to_body(dec.subdomains[s], dofs.num_free()).transpose()) * probe;
  EXPECT_EQ(Cu, C_body * probe);
  // the cut's dofs are in both subdomains: each copy takes half of every coefficient
  EXPECT_EQ(C[0].nonZeros(), rows);
  EXPECT_EQ(C[1].nonZeros(), rows);
  for (const SparseMatrix& part : C)
    for (int j = 0; j < part.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(part, j); it; ++it) EXPECT_EQ(it.value(), 1.0);

  BlockSystem sys;
  Group other;
  other.name = "other";
  other.K = SparseMatrix(3, 3);
  other.C = SparseMatrix(2, 3);
  other.C.insert(1, 2) = 1.0;
  sys.groups.push_back(other);
  sys.d = Eigen::VectorXd::Constant(2, 7.0);
  const SparseMatrix B1 = dec.groups[1].C;
  append_to_system(sys, dec);
  ASSERT_EQ(sys.groups.size(), 3u);
  EXPECT_TRUE(dec.groups.empty());
  EXPECT_EQ(sys.num_multipliers(), 2 + mD);
  EXPECT_EQ(sys.d.head(2), Eigen::VectorXd::Constant(2, 7.0));
  EXPECT_EQ(sys.d.tail(mD), Eigen::VectorXd::Zero(mD));
  for (const Group& g : sys.groups) EXPECT_EQ(g.C.rows(), 2 + mD);
  EXPECT_EQ(sys.groups[0].C.coeff(1, 2), 1.0);
  EXPECT_EQ(Eigen::MatrixXd(sys.groups[2].C).bottomRows(mD), Eigen::MatrixXd(B1));
  EXPECT_EQ(Eigen::MatrixXd(sys.groups[2].C).topRows(2).norm(), 0.0);
  EXPECT_EQ(sys.groups[1].name, "block/0");
}

}  // namespace test_subdomain_decomposition
