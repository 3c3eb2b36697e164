// Contact search on the paper's Example 1 samples: the multiplier counts the paper prints (Tables II and III)
// follow from the geometry — 22 / 30 / 38 in 2D, 63 / 105 / 195 in 3D — and node-to-segment projection basics.
#include <gtest/gtest.h>

#include <filesystem>

#include "contact/ContactConstraints.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_contact_counts {

using namespace rollsim;

namespace {
long multipliers(const std::string& sample) {
  const Model model = build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / sample));
  return static_cast<long>(contact_rows(model, search_contacts(model)).size());
}
}  // namespace

TEST(ContactCounts, Example1MultipliersMatchThePaper) {
  EXPECT_EQ(multipliers("block-indent-2d-50x30.json"), 22);
  EXPECT_EQ(multipliers("block-indent-2d-70x50.json"), 30);
  EXPECT_EQ(multipliers("block-indent-2d-90x70.json"), 38);
  EXPECT_EQ(multipliers("block-indent-3d-10x6x4.json"), 63);
  EXPECT_EQ(multipliers("block-indent-3d-20x6x4.json"), 105);
  EXPECT_EQ(multipliers("block-indent-3d-20x12x4.json"), 195);
}

TEST(ContactSearch, NodeToSegmentGivesWeightsNormalAndGap) {
  // master: one Q4 [0,2]x[-1,0]; its top edge (local 2) runs from (2,0) to (0,0), outward normal +y
  Mesh master;
  master.nodes = {{0, -1, 0}, {2, -1, 0}, {2, 0, 0}, {0, 0, 0}};
  master.connectivity = {0, 1, 2, 3};
  // slave: one Q4 [0.5,1]x[0.1,0.6]; its bottom edge (local 0) holds nodes at (0.5,0.1) and (1,0.1)
  Mesh slave;
  slave.nodes = {{0.5, 0.1, 0}, {1, 0.1, 0}, {1, 0.6, 0}, {0.5, 0.6, 0}};
  slave.connectivity = {0, 1, 2, 3};
  const auto points = find_contact_points(slave, {{0, 0}}, master, {{0, 2}}, 0.2);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].slave_node, 0);
  EXPECT_NEAR(points[0].gap, 0.1, 1e-14);
  EXPECT_NEAR(points[0].normal.y(), 1.0, 1e-14);
  EXPECT_NEAR(points[0].weight, 0.25, 1e-14);
  // (0.5, 0) on the edge from (2,0) [node 2] to (0,0) [node 3]: N = (0.25, 0.75)
  EXPECT_EQ(points[0].master_nodes, (std::vector<int>{2, 3}));
  EXPECT_NEAR(points[0].N[0], 0.25, 1e-14);
  EXPECT_NEAR(points[0].N[1], 0.75, 1e-14);
  EXPECT_TRUE(find_contact_points(slave, {{0, 0}}, master, {{0, 2}}, 0.05).empty()) << "beyond the search distance";
}

}  // namespace test_contact_counts
