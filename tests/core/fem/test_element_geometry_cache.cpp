// ElementGeometryCache: the finite-strain kernel's reference gradients kept between assemblies. An entry is the
// gradients of the coordinates it is asked at, bit for bit, even after the element's nodes moved (an ALE step or a
// remesh moves a reference mesh under the same Assembler), an inverted element has none, and a body beyond the cache's
// memory budget is computed element by element as before.
#include <gtest/gtest.h>

#include <limits>

#include "../../common/FiniteBlock.h"
#include "fem/Assembler.h"
#include "mesh/StructuredBlock.h"
#include "model/DofMap.h"

namespace test_element_geometry_cache {

using namespace rollsim;

namespace {
SolidElement<2>::Coords unit_square() {
  SolidElement<2>::Coords x;
  x << 0, 1, 1.1, 0, 0, 0, 1, 0.9;
  return x;
}

void expect_same(const SolidElement<2>::Geometry& a, const SolidElement<2>::Geometry& b) {
  for (int p = 0; p < SolidElement<2>::NGP; ++p) {
    EXPECT_EQ(a.dN[p], b.dN[p]) << "point " << p;
    EXPECT_EQ(a.dv[p], b.dv[p]) << "point " << p;
  }
  EXPECT_EQ(a.centre, b.centre);
}
}  // namespace

TEST(ElementGeometryCache, GivesTheGradientsOfTheCoordinatesItIsAskedAt) {
  ElementGeometryCache<2> cache;
  cache.resize(2);
  SolidElement<2>::Coords x = unit_square();
  SolidElement<2>::Geometry fresh;
  ASSERT_TRUE(SolidElement<2>::gradients(x, fresh));
  SolidElement<2>::Geometry scratch;
  const SolidElement<2>::Geometry* kept = cache.at(1, x, scratch);
  ASSERT_NE(kept, nullptr);
  expect_same(*kept, fresh);
  x(0, 2) += 0.25;  // a node moved: the entry is computed again
  ASSERT_TRUE(SolidElement<2>::gradients(x, fresh));
  kept = cache.at(1, x, scratch);
  ASSERT_NE(kept, nullptr);
  expect_same(*kept, fresh);
  EXPECT_NE(kept, &scratch);  // the cache's own entry
  x.col(2).swap(x.col(3));    // folded: no geometry
  EXPECT_EQ(cache.at(1, x, scratch), nullptr);
}

// A body too large for the cache's budget keeps nothing: each element's geometry is computed where it is asked.
TEST(ElementGeometryCache, ABodyBeyondItsBudgetIsComputedEachTime) {
  ElementGeometryCache<2> cache;
  cache.resize(std::numeric_limits<int>::max());  // ~2e9 entries: far beyond kElementCacheBytes, and allocates none
  const SolidElement<2>::Coords x = unit_square();
  SolidElement<2>::Geometry fresh, scratch;
  ASSERT_TRUE(SolidElement<2>::gradients(x, fresh));
  const SolidElement<2>::Geometry* got = cache.at(123456789, x, scratch);
  ASSERT_EQ(got, &scratch);
  expect_same(*got, fresh);
}

// An Assembler whose body's reference nodes move between assemblies (as ALE moves them) assembles what a fresh
// Assembler on the moved mesh does.
TEST(ElementGeometryCache, AnAssemblyAfterTheMeshMovedIsThatOfTheMovedMesh) {
  Body body = testing_support::finite_block(2, {3, 2, 1});
  const DofMap dofs(body, 0, {});
  const Assembler kept(body, dofs);
  Eigen::VectorXd u(body.mesh.num_nodes() * 2);
  for (int n = 0; n < body.mesh.num_nodes(); ++n)
    for (int c = 0; c < 2; ++c) u[n * 2 + c] = 0.01 * (c + 1) * body.mesh.nodes[n][c] * body.mesh.nodes[n][1 - c];
  auto assemble = [&](const Assembler& a, SparseMatrix& K, Eigen::VectorXd& f) {
    IntegrationState state = IntegrationState::initial(body);
    EXPECT_LT(a.assemble(u, &K, f, state), 0);
  };
  SparseMatrix K0, K1, K2;
  Eigen::VectorXd f0, f1, f2;
  assemble(kept, K0, f0);
  for (auto& node : body.mesh.nodes) node[0] += 0.1 * node[1] * node[1];  // the reference moves
  assemble(kept, K1, f1);
  const Assembler fresh(body, dofs);
  assemble(fresh, K2, f2);
  EXPECT_GT((f1 - f0).norm(), 1e-6 * f0.norm());  // the move matters
  EXPECT_EQ(f1, f2);
  EXPECT_EQ(Eigen::MatrixXd(K1), Eigen::MatrixXd(K2));
}

}  // namespace test_element_geometry_cache
