// Large sliding searches a pair again in the current configuration. A slave node that comes within the search distance
// for the first time joins the pair with a fresh state, and every node already in the pair keeps its own: the points
// and their states stay aligned. (They did not: a new node's state was appended without its point, so every later
// point took its neighbour's stick anchor and active flag, and the rolling pass diverged near 7 mm of travel.) Found
// again after an ALE step, a point the step's placement left off the master is inactive.
#include <gtest/gtest.h>

#include <filesystem>

#include "contact/ContactConstraints.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_follow_contacts {

using namespace rollsim;

TEST(FollowContacts, NodeNewToThePairKeepsEveryOtherPointsState) {
  Model model =
      build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / "cylinder-indent-2d.json"));
  ContactPair& pair = model.contacts.at(0);
  const double wide = pair.search_distance;
  pair.search_distance = 0.2 * wide;  // the first search sees fewer nodes than the second
  std::vector<PairState> pairs = search_contacts(model);
  const size_t before = pairs[0].points.size();
  ASSERT_GT(before, 0u);
  for (size_t j = 0; j < before; ++j) {  // tag each point's state with its node
    pairs[0].slid[j] = pairs[0].points[j].slave_node;
    pairs[0].normal_force[j] = 1.0 + pairs[0].points[j].slave_node;
  }
  std::vector<Eigen::VectorXd> u;
  for (const Body& b : model.bodies) u.push_back(Eigen::VectorXd::Zero(b.mesh.num_nodes() * model.dim));
  pair.search_distance = wide;
  pair.sliding = ContactPair::Sliding::Step;
  follow_contacts(model, u, pairs, ContactPair::Sliding::Step);

  const PairState& now = pairs[0];
  ASSERT_GT(now.points.size(), before) << "the wider search finds new nodes";
  for (const auto* v : {&now.slid, &now.normal_force}) ASSERT_EQ(v->size(), now.points.size());
  ASSERT_EQ(now.active.size(), now.points.size());
  ASSERT_EQ(now.anchor.size(), now.points.size());
  size_t kept = 0, fresh = 0;
  for (size_t j = 0; j < now.points.size(); ++j) {
    const int node = now.points[j].slave_node;
    if (now.normal_force[j] == 0.0) {  // new: a fresh state
      EXPECT_EQ(now.slid[j], 0.0) << "node " << node;
      ++fresh;
      continue;
    }
    EXPECT_EQ(now.slid[j], node) << "node " << node << " carries another point's state";
    EXPECT_EQ(now.normal_force[j], 1.0 + node);
    ++kept;
  }
  EXPECT_EQ(kept, before);
  EXPECT_EQ(fresh, now.points.size() - before);
}

TEST(RefindContacts, APointPutOffTheMasterIsInactiveAndOneOnItKeepsItsStatus) {
  // after an ALE step the slave body's nodes are put back: a point left off the master would be pulled back onto it
  // by its row (adding the gap's material to the window), so it starts the next step free
  const Model model =
      build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / "cylinder-indent-2d.json"));
  const ContactPair& pair = model.contacts.at(0);
  std::vector<PairState> pairs = search_contacts(model);
  ASSERT_GT(pairs[0].points.size(), 1u);
  size_t touching = 0;
  for (size_t j = 0; j < pairs[0].points.size(); ++j) {
    pairs[0].active[j] = 1;  // all in, whatever their gap
    pairs[0].normal_force[j] = 1.0 + pairs[0].points[j].slave_node;
    touching += pairs[0].points[j].gap <= 1e-9 * pair.search_distance;
  }
  ASSERT_GT(touching, 0u);
  ASSERT_LT(touching, pairs[0].points.size());
  std::vector<Eigen::VectorXd> u;
  for (const Body& b : model.bodies) u.push_back(Eigen::VectorXd::Zero(b.mesh.num_nodes() * model.dim));
  refind_contacts(model, u, pair.slave_body, pairs);
  size_t active = 0;
  for (size_t j = 0; j < pairs[0].points.size(); ++j) {
    const bool on = pairs[0].points[j].gap <= 1e-9 * pair.search_distance;
    EXPECT_EQ(pairs[0].active[j] != 0, on) << "node " << pairs[0].points[j].slave_node;
    EXPECT_EQ(pairs[0].normal_force[j], 1.0 + pairs[0].points[j].slave_node) << "its state stays its own";
    active += pairs[0].active[j];
  }
  EXPECT_EQ(active, touching);
}

}  // namespace test_follow_contacts
