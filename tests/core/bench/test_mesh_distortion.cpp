// Randomly distorted meshes keep their boundary (and every named node set) and move interior nodes by at most the
// fraction of the shortest incident edge asked for.
#include <gtest/gtest.h>

#include <cmath>

#include "bench/MeshDistortion.h"
#include "mesh/StructuredBlock.h"

namespace test_mesh_distortion {

using namespace rollsim;

TEST(MeshDistortion, MovesInteriorNodesWithinTheFractionAndKeepsTheBoundary) {
  BlockSpec s;
  s.n = {8, 8, 1};
  s.size = {1, 1, 1};
  const Mesh before = make_block(s);
  Mesh after = before;
  bench::distort_interior_nodes(after, 0.3, 7);
  int moved = 0;
  for (int n = 0; n < before.num_nodes(); ++n) {
    const double dx = after.nodes[n][0] - before.nodes[n][0], dy = after.nodes[n][1] - before.nodes[n][1];
    const bool boundary = before.nodes[n][0] == 0 || before.nodes[n][0] == 1 || before.nodes[n][1] == 0 ||
                          std::abs(before.nodes[n][1] - 1) < 1e-12 || std::abs(before.nodes[n][0] - 1) < 1e-12;
    if (boundary) {
      EXPECT_EQ(dx, 0.0);
      EXPECT_EQ(dy, 0.0);
    }
    EXPECT_LE(std::abs(dx), 0.3 / 8 + 1e-15);
    EXPECT_LE(std::abs(dy), 0.3 / 8 + 1e-15);
    moved += dx != 0 || dy != 0;
    EXPECT_EQ(after.nodes[n][2], before.nodes[n][2]) << "2D: z stays";
  }
  EXPECT_EQ(moved, 7 * 7) << "every interior node moves";
  EXPECT_NO_THROW(check_element_orientation(after));
}

}  // namespace test_mesh_distortion
