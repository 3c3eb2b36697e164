// Nodes moved back to their original spread (mesh/EvenNodes): a mesh moved rigidly or stretched uniformly is its own
// answer; the boundary nodes of a distorted block go back to their graded fractions along each side, the corners
// stay; the inner nodes follow and no element folds. A free side that crossed a stuck face's line folds onto it, the
// corner following to where the side crosses back.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/ElementQuality.h"
#include "mesh/EvenNodes.h"
#include "mesh/StructuredBlock.h"

namespace test_even_nodes {

using namespace rollsim;
using Points = std::vector<std::array<double, 3>>;

namespace {
Mesh block(int nx, int ny, double grading = 1.0) {
  BlockSpec s;
  s.n = {nx, ny, 1};
  s.size = {10.0, 6.0, 1.0};
  s.grading = {1.0, grading, 1.0};
  return make_block(s);
}

template <class F>
Points mapped(const Mesh& m, F f) {
  Points x;
  for (const auto& p : m.nodes) x.push_back(f(p));
  return x;
}

double farthest(const Points& a, const Points& b) {
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::hypot(a[i][0] - b[i][0], a[i][1] - b[i][1]));
  return d;
}
}  // namespace

TEST(EvenNodes, AnAffineMotionIsItsOwnAnswer) {
  const Mesh m = block(8, 5, 1.3);
  const Points x = mapped(m, [](const auto& p) {  // stretch, shear and turn
    return std::array<double, 3>{0.8 * p[0] + 0.3 * p[1] + 2, -0.2 * p[0] + 1.4 * p[1] - 1, 0};
  });
  EXPECT_LT(farthest(even_nodes(m, x), x), 1e-10);
}

TEST(EvenNodes, ASideSlidNodeGoesBackToItsFractionAndTheCornersStay) {
  const Mesh m = block(8, 8, 1.2);  // graded across y: the xmax side's fractions are uneven
  Points x = m.nodes;
  // barrel the xmax side (x = 10 + 0.2 sin(π y / 6)) and slide its nodes toward the top
  for (size_t i = 0; i < x.size(); ++i) {
    const double y = m.nodes[i][1], t = y / 6.0;
    const double slid = m.nodes[i][0] == 10.0 ? y + 0.8 * std::sin(M_PI * t) : y;
    x[i] = {m.nodes[i][0] + m.nodes[i][0] / 50.0 * std::sin(M_PI * slid / 6.0), slid, 0};
  }
  const Points y = even_nodes(m, x);
  for (int n : m.node_sets.at("xmax")) {
    EXPECT_NEAR(y[n][1], m.nodes[n][1], 0.02) << "node " << n;  // back at its graded height (on the curve)
    // on the barrel, within the sag of its chords
    EXPECT_NEAR(y[n][0], 10.0 + 0.2 * std::sin(M_PI * y[n][1] / 6.0), 0.015) << "node " << n;
  }
  for (int corner : {0, m.num_nodes() - 1}) EXPECT_EQ(y[corner], x[corner]);
  for (int e = 0; e < m.num_elements(); ++e) {
    Mesh moved = m;
    moved.nodes = y;
    EXPECT_GT(corner_sine(moved, moved.nodes, e), 0.5) << "element " << e;
  }
}

TEST(EvenNodes, ANodeOfItsOwnSetStays) {
  Mesh m = block(6, 3);
  const int pinned = m.node_sets.at("ymax")[3];
  m.node_sets["pin"] = {pinned};
  Points x = m.nodes;
  for (int n : m.node_sets.at("ymax")) x[n][0] += 0.3 * std::sin(x[n][0]);
  const Points y = even_nodes(m, x);
  EXPECT_EQ(y[pinned], x[pinned]);
}

TEST(EvenNodes, ASideThatCrossedAStuckFaceFoldsOntoItAndTheCornerFollows) {
  const Mesh m = block(4, 4);  // 10 × 6: the xmax side's nodes at y = 0, 1.5, 3, 4.5, 6
  Points x = m.nodes;
  const std::vector<int>& top = m.node_sets.at("ymax");
  int corner = -1, below = -1;  // the top-right corner and the side node under it
  for (int n = 0; n < m.num_nodes(); ++n) {
    if (m.nodes[n][0] == 10.0 && m.nodes[n][1] == 6.0) corner = n;
    if (m.nodes[n][0] == 10.0 && m.nodes[n][1] == 4.5) below = n;
  }
  ASSERT_GE(corner, 0);
  ASSERT_GE(below, 0);
  x[below] = {10.5, 6.4, 0};  // past the top face's line y = 6: the side folded over the tool
  const Points y = even_nodes(m, x, {}, {top});
  // the free side crosses back over y = 6 between (10.5, 6.4) and (10, 3): there the corner now is
  const double t = 0.4 / 3.4;
  EXPECT_NEAR(y[corner][0], 10.5 - 0.5 * t, 1e-12);
  EXPECT_NEAR(y[corner][1], 6.0, 1e-12);
  for (int n : top) EXPECT_NEAR(y[n][1], 6.0, 1e-12) << "node " << n;  // the face stays on its line
  EXPECT_LT(y[below][1], 6.0);                                         // the folded node is back on the free side
  for (int e = 0; e < m.num_elements(); ++e) EXPECT_GT(corner_sine(m, y, e), 0.2) << "element " << e;
  // without the face the corner stays where it is
  EXPECT_EQ(even_nodes(m, x)[corner], x[corner]);
}

TEST(EvenNodes, RefusesHexahedra) {
  BlockSpec s;
  s.dim = 3;
  const Mesh m = make_block(s);
  EXPECT_THROW(even_nodes(m, m.nodes), std::invalid_argument);
}

}  // namespace test_even_nodes
