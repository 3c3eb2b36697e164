// Constraint rows on the bodies' free dofs (analysis/ConstraintAssembly): a prescribed term moves to the right-hand
// side, a row on prescribed dofs only is dropped, and each kept row names the body of its first free term — a
// contact row's slave, or its master where the slave's terms are all prescribed (what preconditions the row:
// solve/InterfacePreconditioner). A sticking point whose motion along an axis the supports hold on both sides keeps one
// tangential row, across that axis.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/ConstraintAssembly.h"
#include "mesh/StructuredBlock.h"

namespace test_constraint_assembly {

using namespace rollsim;

namespace {
/// Two 1 × 1 square bodies; node 0 of body 0 has its y prescribed to 0.5 (at load factor 1).
std::vector<std::unique_ptr<DofMap>> two_bodies(std::vector<Body>& bodies) {
  BlockSpec s;
  s.n = {1, 1, 1};
  s.size = {1.0, 1.0, 1.0};
  bodies.resize(2);
  for (Body& b : bodies) b.mesh = make_block(s);
  DisplacementBC bc{0, "pin", {0}, {}};
  bc.value[1] = 0.5;
  std::vector<std::unique_ptr<DofMap>> dofs;
  dofs.push_back(std::make_unique<DofMap>(bodies[0], 0, std::vector<DisplacementBC>{bc}));
  dofs.push_back(std::make_unique<DofMap>(bodies[1], 1, std::vector<DisplacementBC>{}));
  return dofs;
}

/// u(0, node 0, comp) − u(1, node 0, comp) = 0: slave body 0, master body 1
ConstraintRow between(int comp) {
  ConstraintRow row;
  row.terms = {{0, 0, comp, 1.0}, {1, 0, comp, -1.0}};
  return row;
}
}  // namespace

TEST(ConstraintAssembly, EachRowNamesTheBodyOfItsFirstFreeTerm) {
  std::vector<Body> bodies;
  const auto dofs = two_bodies(bodies);
  ConstraintRow prescribed_only;
  prescribed_only.terms = {{0, 0, 1, 2.0}};
  const BodyConstraints c = body_constraints({between(0), between(1), prescribed_only}, dofs);
  ASSERT_EQ(c.kept, (std::vector<int>{0, 1}));        // the third row is on a prescribed dof only
  EXPECT_EQ(c.slave_body, (std::vector<int>{0, 1}));  // x: the slave's own; y: the slave's is prescribed
  EXPECT_DOUBLE_EQ(c.d[0], 0.0);
  EXPECT_DOUBLE_EQ(c.d[1], -0.5);  // its prescribed 0.5 moved to the right-hand side
  EXPECT_EQ(c.C[0].nonZeros(), 1);
  EXPECT_EQ(c.C[1].nonZeros(), 2);
}

namespace {
/// A sticking point of slave node 0 of body 0 over nodes 0 and 1 of body 1 (weights 0.5), normal z, tangents turned
/// 30° about it; `held_master` nodes of body 1 (and the slave node) have their y prescribed to 0.
struct StickingPoint {
  std::vector<Body> bodies{2};
  std::vector<std::unique_ptr<DofMap>> dofs;
  std::vector<ConstraintRow> rows;
};

ConstraintRow along(const Eigen::Vector3d& dir, int comp, double rhs) {
  ConstraintRow row;
  row.comp = comp, row.dir = dir, row.rhs = rhs;
  for (int k = 0; k < 3; ++k)
    row.terms.insert(row.terms.end(), {{0, 0, k, dir[k]}, {1, 0, k, -0.5 * dir[k]}, {1, 1, k, -0.5 * dir[k]}});
  return row;
}

StickingPoint sticking_point(std::vector<int> held_master) {
  StickingPoint p;
  BlockSpec s;
  s.dim = 3;
  s.n = {1, 1, 1};
  s.size = {1.0, 1.0, 1.0};
  for (Body& b : p.bodies) b.mesh = make_block(s);
  DisplacementBC slave{0, "slave", {0}, {}}, master{1, "master", held_master, {}};
  slave.value[1] = 0.0, master.value[1] = 0.0;
  p.dofs.push_back(std::make_unique<DofMap>(p.bodies[0], 0, std::vector<DisplacementBC>{slave}));
  p.dofs.push_back(std::make_unique<DofMap>(p.bodies[1], 1, std::vector<DisplacementBC>{master}));
  const double c = std::cos(M_PI / 6), sn = std::sin(M_PI / 6);
  p.rows = {along({0, 0, 1}, -1, 0.0), along({c, sn, 0}, 0, 1.0), along({-sn, c, 0}, 1, 2.0)};
  return p;
}
}  // namespace

TEST(ConstraintAssembly, ASlipDirectionTheSupportsHoldOnBothSidesLeavesOneTangentialRow) {
  StickingPoint p = sticking_point({0, 1});
  hold_supported_tangents(p.rows, p.dofs);
  ASSERT_EQ(p.rows.size(), 2u);
  const ConstraintRow& t = p.rows[1];
  EXPECT_EQ(t.comp, kSupportedTangent);
  EXPECT_NEAR((t.dir - Eigen::Vector3d(-1, 0, 0)).norm(), 0.0, 1e-15);  // n × e_y
  // the same constraint as the two rows', along −x: −cos 30° · 1 + sin 30° · 2
  EXPECT_NEAR(t.rhs, -std::cos(M_PI / 6) + 2 * std::sin(M_PI / 6), 1e-15);
  const BodyConstraints c = body_constraints(p.rows, p.dofs);
  ASSERT_EQ(c.kept.size(), 2u);
  const Eigen::MatrixXd slave(c.C[0]), master(c.C[1]);
  EXPECT_NEAR(slave.row(1).cwiseAbs().sum(), 1.0, 1e-15);   // −1 on the slave's x
  EXPECT_NEAR(master.row(1).cwiseAbs().sum(), 1.0, 1e-15);  // 0.5 on each master node's x
  EXPECT_NEAR(slave(1, p.dofs[0]->equation(0, 0)), -1.0, 1e-15);
}

TEST(ConstraintAssembly, AMasterNodeFreeAlongTheAxisKeepsBothTangentialRows) {
  StickingPoint p = sticking_point({0});
  hold_supported_tangents(p.rows, p.dofs);
  ASSERT_EQ(p.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(p.rows[2].rhs, 2.0);
}

}  // namespace test_constraint_assembly
