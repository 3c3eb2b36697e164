// The three kinds of partition (structured slicing, METIS, explicit map) and their validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "PartitionFixtures.h"
#include "partition/MetisPartition.h"
#include "partition/PartitionCheck.h"
#include "partition/StructuredPartition.h"

namespace test_partition_kinds {

using namespace rollsim;

namespace {
/// Index slicing of a unit-element block, computed from element indices, not positions.
int index_slice(const Mesh& m, int e, const std::array<int, 3>& n, const std::array<int, 3>& s) {
  std::array<int, 3> piece{0, 0, 0};
  for (int a = 0; a < m.dim; ++a) {
    double lo = 1e300;
    for (int k = 0; k < m.nodes_per_elem(); ++k) lo = std::min(lo, m.nodes[m.element(e)[k]][a]);
    piece[a] = static_cast<int>(std::lround(lo)) * s[a] / n[a];
  }
  return piece[0] + s[0] * (piece[1] + s[1] * piece[2]);
}

std::vector<PartitionProblem> problems_of(const Mesh& mesh, std::vector<int> map, int n) {
  return check_partition(mesh, Partition{n, std::move(map), "explicit"});
}
}  // namespace

TEST(PartitionKinds, StructuredSlicingIsIndexSlicing) {
  const Model square = test::block_model(2, {120, 120, 1});
  for (std::array<int, 3> s : {std::array<int, 3>{2, 2, 1}, {4, 4, 1}, {1, 8, 1}, {8, 1, 1}, {10, 10, 1}, {3, 2, 1}}) {
    const Partition p = structured_partition(square.bodies[0].mesh, s);
    ASSERT_EQ(p.num_subdomains, s[0] * s[1]);
    for (int e = 0; e < square.bodies[0].mesh.num_elements(); ++e)
      ASSERT_EQ(p.element_subdomain[e], index_slice(square.bodies[0].mesh, e, {120, 120, 1}, s)) << p.description;
    EXPECT_TRUE(check_partition(square.bodies[0].mesh, p).empty());
  }
  const Model box = test::block_model(3, {32, 16, 8});
  for (std::array<int, 3> s : {std::array<int, 3>{4, 2, 2}, {8, 4, 2}, {1, 1, 2}, {2, 4, 2}}) {
    const Partition p = structured_partition(box.bodies[0].mesh, s);
    for (int e = 0; e < box.bodies[0].mesh.num_elements(); ++e)
      ASSERT_EQ(p.element_subdomain[e], index_slice(box.bodies[0].mesh, e, {32, 16, 8}, s)) << p.description;
  }
}

TEST(PartitionKinds, StructuredSlicingOfUnevenCountsIsBalanced) {
  const Model m = test::block_model(2, {10, 7, 1});
  const Partition p = structured_partition(m.bodies[0].mesh, {3, 2, 1});
  std::vector<int> sizes;
  for (const auto& list : subdomain_elements(p)) sizes.push_back(static_cast<int>(list.size()));
  EXPECT_LE(*std::max_element(sizes.begin(), sizes.end()) - *std::min_element(sizes.begin(), sizes.end()), 7);
  EXPECT_TRUE(check_partition(m.bodies[0].mesh, p).empty());
}

TEST(PartitionKinds, ExplicitMapGivesTheSameGroupsAsStructured) {
  Model m = test::block_model(2, {12, 6, 1});
  test::support(m, test::nodes_in_box(m, {0, 0, 0}, {0, 6, 0}));
  test::support(m, test::nodes_in_box(m, {12, 6, 0}, {12, 6, 0}), 1, 0.5);
  const Partition structured = structured_partition(m.bodies[0].mesh, {3, 2, 1});
  const Partition painted{6, structured.element_subdomain, "explicit"};
  const BodyDecomposition a = decompose_body(m, 0, structured), b = decompose_body(m, 0, painted);
  ASSERT_EQ(a.groups.size(), b.groups.size());
  for (size_t s = 0; s < a.groups.size(); ++s) {
    EXPECT_EQ((a.groups[s].K - b.groups[s].K).norm(), 0.0);
    EXPECT_EQ((a.groups[s].f - b.groups[s].f).norm(), 0.0);
    EXPECT_EQ((a.groups[s].C - b.groups[s].C).norm(), 0.0);
    EXPECT_EQ(a.groups[s].R, b.groups[s].R);
    EXPECT_EQ(a.subdomains[s].free_dofs, b.subdomains[s].free_dofs);
  }
}

TEST(PartitionKinds, MetisPartitionsAreValidConnectedAndDeterministic) {
  const Model square = test::block_model(2, {40, 40, 1});
  const Model cube = test::block_model(3, {8, 8, 8});
  const Model plate = test::sample_model("plate-hole-2d");
  for (const Model* m : {&square, &cube, &plate})
    for (int parts : {2, 5, 16}) {
      const Mesh& mesh = m->bodies[0].mesh;
      const Partition p = metis_partition(mesh, parts);
      EXPECT_EQ(p.description, "metis:" + std::to_string(parts));
      const auto problems = check_partition(mesh, p);
      EXPECT_TRUE(problems.empty()) << (problems.empty() ? "" : problems.front().message);
      size_t largest = 0;
      for (const auto& list : subdomain_elements(p)) largest = std::max(largest, list.size());
      EXPECT_LE(static_cast<double>(largest), 1.1 * mesh.num_elements() / parts + 1) << "METIS balance";
      EXPECT_EQ(metis_partition(mesh, parts).element_subdomain, p.element_subdomain);
    }
}

TEST(PartitionCheck, ReportsLengthRangeAndEmptySubdomains) {
  const Mesh mesh = test::block_model(2, {4, 4, 1}).bodies[0].mesh;
  auto p = problems_of(mesh, std::vector<int>(15, 0), 1);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].path, "partition.map");
  EXPECT_EQ(p[0].message, "has 15 entries, but the body has 16 elements (one subdomain id per element)");

  std::vector<int> map(16, 0);
  map[3] = 7;
  map[9] = -1;
  p = problems_of(mesh, map, 2);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].path, "partition.map[3]");
  EXPECT_EQ(p[0].message, "element 3: subdomain id 7 is out of range 0..1 (and 1 more elements out of range)");

  p = problems_of(mesh, std::vector<int>(16, 0), 3);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].path, "partition.subdomains[1]");
  EXPECT_EQ(p[0].message, "subdomain 1 has no elements");
  EXPECT_EQ(p[1].path, "partition.subdomains[2]");
  EXPECT_EQ(problems_of(mesh, {}, 0).front().path, "partition.map");
}

TEST(PartitionCheck, DisconnectedPiecesAreReportedAndSplit) {
  Model m = test::block_model(2, {4, 4, 1});
  const Mesh& mesh = m.bodies[0].mesh;
  // subdomain 1 = the two left corner columns' bottom element and top element: pieces that share no edge
  Partition p = structured_partition(mesh, {1, 1, 1});
  p.num_subdomains = 2;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto& x = mesh.nodes[mesh.element(e)[0]];
    if (x[0] < 0.5 && (x[1] < 0.5 || x[1] > 2.5)) p.element_subdomain[e] = 1;
  }
  const auto problems = check_partition(mesh, p, "bodies[0].partition");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].path, "bodies[0].partition.subdomains[1]");
  EXPECT_EQ(problems[0].message,
            "subdomain 1 is made of 2 disconnected pieces (1 and 1 elements) that share no edge; split it (automatic "
            "splitting is available) or repaint it");
  const auto warnings = split_disconnected(mesh, p);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "subdomain 1 was made of 2 disconnected pieces (1 and 1 elements); split automatically into subdomains 1 "
            "and 2");
  EXPECT_EQ(p.num_subdomains, 3);
  EXPECT_TRUE(check_partition(mesh, p).empty());
}

TEST(PartitionCheck, PointAndEdgeContactsAreNotConnections) {
  // 2D: two elements touching at one node are a hinge; 3D: two elements sharing only an edge as well
  const Mesh square = test::block_model(2, {2, 2, 1}).bodies[0].mesh;
  std::vector<int> diagonal(4, 0);
  for (int e = 0; e < 4; ++e) {
    const auto& x = square.nodes[square.element(e)[0]];
    diagonal[e] = (x[0] < 0.5) == (x[1] < 0.5) ? 0 : 1;
  }
  EXPECT_EQ(problems_of(square, diagonal, 2).size(), 2u);
  const Mesh cube = test::block_model(3, {2, 2, 1}).bodies[0].mesh;
  EXPECT_EQ(problems_of(cube, diagonal, 2).size(), 2u);

  Model m = test::block_model(2, {2, 2, 1});
  test::support(m, test::nodes_in_box(m, {0, 0, 0}, {0, 2, 0}));
  const BodyDecomposition dec = decompose_body(m, 0, Partition{2, diagonal, "explicit"});
  EXPECT_EQ(dec.partition.num_subdomains, 4);
  ASSERT_EQ(dec.warnings.size(), 2u);
  EXPECT_EQ(dec.warnings[0].rfind("bodies[0].partition: subdomain 0 was made of 2 disconnected pieces", 0), 0u);
  DecomposeOptions strict;
  strict.split_disconnected = false;
  EXPECT_THROW(decompose_body(m, 0, Partition{2, diagonal, "explicit"}, strict), PartitionError);
}

}  // namespace test_partition_kinds
