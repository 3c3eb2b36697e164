// A master surface whose material turns under a mesh that stays (ContactPair::master_turns: a fixed roll). Its true
// surface is the circle through its nodes, not its facets' chords: a point on the circle touches (gap 0) wherever it
// lies on a facet, the facet's sagitta its offset. Where a step begins, each point is projected where the material
// carries it, and a sticking point's anchor moves with the material; a point that moved with the material has not
// slipped.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "contact/ContactConstraints.h"
#include "contact/Friction.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_turning_master {

using namespace rollsim;

namespace {
constexpr double kRadius = 300, kAround = 40;  // a coarse roll: facets of 47 mm, their sagitta L²/8R 0.92 mm

/// The paper's plane-strain pass as an ALE window (its top cut to the roll over the arc) on a coarse roll, fixed or
/// turning.
Model pass(const std::string& roll_mesh) {
  const nlohmann::json j = {{"dimension", 2},
                            {"process",
                             {{"type", "rolling"},
                              {"formulation", "ale"},
                              {"slab_nx", 20},
                              {"roll_n_around", kAround},
                              {"roll_mesh", roll_mesh}}}};
  return build_model(parse_project(j.dump(), "pass"));
}

std::vector<Eigen::VectorXd> at_rest(const Model& m) {
  std::vector<Eigen::VectorXd> u;
  for (const Body& b : m.bodies) u.push_back(Eigen::VectorXd::Zero(b.mesh.num_nodes() * m.dim));
  return u;
}

Eigen::Vector3d node(const Model& m, int body, int n) {
  const auto& x = m.bodies[static_cast<size_t>(body)].mesh.nodes[static_cast<size_t>(n)];
  return {x[0], x[1], x[2]};
}
}  // namespace

TEST(TurningMaster, AFixedRollsSurfaceIsItsCircleNotItsFacetsChords) {
  const Model fixed = pass("fixed");
  const ContactPair& p = fixed.contacts.at(0);
  ASSERT_TRUE(p.master_turns.has_value());
  const Eigen::Vector3d centre(p.master_turns->center.data());
  const std::vector<PairState> pairs = search_contacts(fixed);
  const double sagitta = kRadius * (1 - std::cos(M_PI / kAround));
  int on_circle = 0;
  double deepest = 0;
  for (size_t j = 0; j < pairs[0].points.size(); ++j) {
    const ContactPoint& c = pairs[0].points[j];
    if (std::abs((node(fixed, p.slave_body, c.slave_node) - centre).norm() - kRadius) > 1e-9) continue;
    ++on_circle;  // the window's top cut to the roll's circle over the arc: every such node touches
    EXPECT_NEAR(c.gap, 0, 1e-9) << c.slave_node;
    EXPECT_TRUE(pairs[0].active[j]);
    EXPECT_GE(c.offset, 0);
    EXPECT_LE(c.offset, sagitta * (1 + 1e-9));
    deepest = std::max(deepest, c.offset);
  }
  EXPECT_GE(on_circle, 2);
  EXPECT_GT(deepest, 0.25 * sagitta) << "a node between the facet's ends lies outside its chord";
  // a turning roll's contact is its facets': no offset, and its window is cut to the chords
  const std::vector<PairState> turning = search_contacts(pass("turning"));
  for (const ContactPoint& c : turning[0].points) EXPECT_EQ(c.offset, 0.0);
}

TEST(TurningMaster, AStepsPointsAreProjectedWhereTheMaterialCarriesThemAndStickToIt) {
  const Model m = pass("fixed");
  const ContactPair& p = m.contacts.at(0);
  const Eigen::Vector3d centre(p.master_turns->center.data());
  std::vector<PairState> pairs = search_contacts(m);
  const std::vector<Eigen::VectorXd> u = at_rest(m);
  const double span = 0.05;  // a twentieth of the pass's turn
  turn_master_surfaces(m, u, span, pairs);
  const double turn = span * p.master_turns->angle;
  EXPECT_DOUBLE_EQ(pairs[0].master_turn, turn);
  const Eigen::AngleAxisd R(turn, Eigen::Vector3d::UnitZ());
  int stuck = 0;
  for (size_t j = 0; j < pairs[0].points.size(); ++j) {
    const ContactPoint& c = pairs[0].points[j];
    const Eigen::Vector3d x = node(m, p.slave_body, c.slave_node), carried = R * (x - centre) + centre;
    const Eigen::Vector3d travel = surface_travel(m, p, pairs[0], c, u);
    EXPECT_LT((x + travel - carried).norm(), 1e-9 * kRadius);
    if (!pairs[0].active[j] || pairs[0].slip[j]) continue;
    // its master point is the carried node's projection on the facet there, on the circle: the sagitta out
    Eigen::Vector3d on_facet = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < c.master_nodes.size(); ++k) on_facet += c.N[k] * node(m, p.master_body, c.master_nodes[k]);
    const Eigen::Vector3d off = carried - on_facet;
    EXPECT_NEAR(c.normal.dot(off), c.offset, 1e-9) << c.slave_node;
    EXPECT_LT((off - c.normal.dot(off) * c.normal).norm(), 1e-9) << c.slave_node;
    ++stuck;  // and it sticks where the material will be: its anchor is its place now moved by the travel
    EXPECT_LT((pairs[0].anchor[j] - relative_position(p, c, u, m.dim) - travel).norm(), 1e-9) << c.slave_node;
  }
  EXPECT_GE(stuck, 2);
  // a pair whose master turns with its mesh is left as it is
  const Model turning = pass("turning");
  std::vector<PairState> kept = search_contacts(turning);
  const std::vector<PairState> before = kept;
  turn_master_surfaces(turning, at_rest(turning), span, kept);
  for (size_t j = 0; j < kept[0].points.size(); ++j) EXPECT_EQ(kept[0].anchor[j], before[0].anchor[j]);
}

TEST(TurningMaster, APointMovedWithTheMaterialHasNotSlipped) {
  const Model m = pass("fixed");
  const ContactPair& p = m.contacts.at(0);
  std::vector<PairState> pairs = search_contacts(m);
  const std::vector<Eigen::VectorXd> start = at_rest(m);
  turn_master_surfaces(m, start, 0.05, pairs);
  std::vector<Eigen::VectorXd> carried = start, held = start;
  for (const ContactPoint& c : pairs[0].points) {
    const Eigen::Vector3d travel = surface_travel(m, p, pairs[0], c, start);
    for (int k = 0; k < m.dim; ++k) carried[p.slave_body][c.slave_node * m.dim + k] = travel[k];
  }
  std::vector<PairState> moved = pairs, stayed = pairs;
  accumulate_slip(m, carried, start, moved);
  accumulate_slip(m, held, start, stayed);  // a point held where it was slid back against the turning material
  int active = 0;
  for (size_t j = 0; j < pairs[0].points.size(); ++j) {
    if (!pairs[0].active[j]) continue;
    ++active;
    EXPECT_NEAR(moved[0].slid[j], 0, 1e-9);
    const double travel = surface_travel(m, p, pairs[0], pairs[0].points[j], start).norm();
    EXPECT_NEAR(stayed[0].slid[j], travel, 0.01 * travel);
  }
  EXPECT_GE(active, 2);
}

}  // namespace test_turning_master
