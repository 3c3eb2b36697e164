// Constraint rows on the bodies' free dofs (analysis/ConstraintAssembly): a prescribed term moves to the right-hand
// side, a row on prescribed dofs only is dropped, and each kept row names the body of its first free term — a
// contact row's slave, or its master where the slave's terms are all prescribed (what preconditions the row:
// solve/InterfacePreconditioner).
#include <gtest/gtest.h>

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

}  // namespace test_constraint_assembly
