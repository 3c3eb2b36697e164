// Tests of the node-graph nested dissection: the runs of equal columns are the nodes, the permutation keeps every
// node's columns together and in order, and it is a permutation (also with dofs removed, nodes of 1-3 columns).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "grid_matrix.h"
#include "solve/NodeOrdering.h"

namespace rollsim::test_node_ordering {
namespace {

using testing::fe_grid_matrix;

TEST(NodeOrdering, RunsAreTheNodes) {
  const SparseMatrix A = fe_grid_matrix(4, 3, 3, 1);  // 125 nodes, 3 dofs each
  const std::vector<int> runs = column_runs(A);
  ASSERT_EQ(runs.size(), 126u);
  for (size_t r = 0; r + 1 < runs.size(); ++r) EXPECT_EQ(runs[r + 1] - runs[r], 3);
  const SparseMatrix B = fe_grid_matrix(6, 2, 2, 2);
  EXPECT_EQ(column_runs(B).size(), 50u);
}

void expect_node_permutation(const SparseMatrix& A) {
  const std::vector<int> runs = column_runs(A);
  const std::vector<int> perm = node_nested_dissection(A);
  ASSERT_EQ(perm.size(), static_cast<size_t>(A.cols()));
  std::vector<int> sorted = perm;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(perm.size());
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity) << "not a permutation";
  // every run appears as a contiguous, increasing block
  for (size_t k = 0; k < perm.size();) {
    const auto r = std::upper_bound(runs.begin(), runs.end(), perm[k]) - runs.begin() - 1;
    ASSERT_EQ(perm[k], runs[static_cast<size_t>(r)]) << "a node does not start with its first column";
    for (int j = runs[static_cast<size_t>(r)]; j < runs[static_cast<size_t>(r) + 1]; ++j, ++k) EXPECT_EQ(perm[k], j);
  }
  EXPECT_NE(perm, identity) << "nested dissection of a grid is not the natural order";
}

TEST(NodeOrdering, KeepsEveryNodesColumnsTogether) {
  expect_node_permutation(fe_grid_matrix(5, 3, 3, 3));
  expect_node_permutation(fe_grid_matrix(12, 2, 2, 4));
  expect_node_permutation(fe_grid_matrix(5, 3, 3, 5, 7));  // dofs removed: nodes of 2 and 3 columns
}

TEST(NodeOrdering, MeanNodeDegreeTellsSquaresFromCubes) {
  // 5 nodes a side: per direction 2 end nodes with 2 neighbours, 3 inner ones with 3: a mean of 2.6 per direction
  EXPECT_NEAR(mean_node_degree(fe_grid_matrix(4, 2, 2, 7)), 2.6 * 2.6, 1e-12);
  EXPECT_NEAR(mean_node_degree(fe_grid_matrix(4, 3, 3, 7)), 2.6 * 2.6 * 2.6, 1e-12);
}

TEST(NodeOrdering, OneNode) {
  const SparseMatrix A = fe_grid_matrix(0, 2, 2, 6);  // a single node: nothing to order
  EXPECT_EQ(node_nested_dissection(A), (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace rollsim::test_node_ordering
