// Large sliding: a small block pressed on a long base and pushed along it by 20 master segments. Each slave node
// travels from segment to segment (the search follows the configuration, where each step begins or at every
// iteration), the frictionless contact carries
// no tangential force, and at the end the contact force equals that of the same press without the slide (the base
// is uniform along x and the slide is a whole number of segments). With small sliding the slave nodes keep their
// first segments: the slider presses the base where it started — the reason large sliding exists.
#include <gtest/gtest.h>

#include <cmath>

#include "../../common/RunJson.h"

namespace test_large_sliding {

using namespace rollsim;
using testing_support::run_json;
using json = nlohmann::json;

namespace {
json slider(double slide, const std::string& sliding, const std::string& mode) {
  auto block = [](const std::string& name, json mesh) {
    return json{{"name", name}, {"material", name}, {"kinematics", "finite"}, {"mesh", mesh}};
  };
  return {
      {"name", "slider"},
      {"dimension", 2},
      {"materials", {{{"name", "base"}, {"E", 1000.0}, {"nu", 0.3}}, {{"name", "slider"}, {"E", 2000.0}, {"nu", 0.3}}}},
      {"bodies",
       {block("base", {{"type", "block"}, {"nx", 60}, {"ny", 2}, {"lx", 30.0}, {"ly", 2.0}}),
        block("slider", {{"type", "block"}, {"nx", 3}, {"ny", 2}, {"lx", 1.5}, {"ly", 1.0}, {"origin", {7.25, 2.0}}})}},
      {"contacts",
       {{{"name", "slide"},
         {"type", "frictionless"},
         {"slave_body", "slider"},
         {"slave_surface", "ymin"},
         {"master_body", "base"},
         {"master_surface", "ymax"},
         {"search_distance", 0.2},
         {"sliding", sliding}}}},
      {"boundary_conditions",
       {{{"type", "displacement"}, {"body", "base"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
        {{"type", "displacement"}, {"body", "slider"}, {"set", "ymax"}, {"ux", slide}, {"uy", -0.02}}}},
      {"analysis", {{"type", "newton"}, {"increments", 20}, {"tolerance", 1e-9}}},
      {"solver", {{"mode", mode}, {"cg_tolerance", 1e-10}}}};
}

/// The reaction of the slider's top (uy = −0.02), component k.
double top_force(const Results& r, int k) { return testing_support::reaction_where_uy(r, 1, 2, -0.02, k); }
}  // namespace

class LargeSliding : public ::testing::TestWithParam<std::string> {};

TEST_P(LargeSliding, ASlideOfTwentySegmentsCarriesNoShearAndTheSameNormalForce) {
  const Results still = run_json(slider(0.0, "large", GetParam()));
  const Results slid = run_json(slider(10.0, "large", GetParam()));
  ASSERT_TRUE(still.status.ok()) << still.status.message;
  ASSERT_TRUE(slid.status.ok()) << slid.status.message;
  const double normal = still.contacts.at(0).normal_force;
  EXPECT_GT(normal, 1.0);
  EXPECT_NEAR(slid.contacts.at(0).normal_force, normal, 1e-4 * normal);  // measured: 2e-5
  EXPECT_EQ(slid.contacts.at(0).active_nodes, still.contacts.at(0).active_nodes);
  EXPECT_LT(std::abs(top_force(slid, 0)), 1e-5 * normal);  // frictionless: nothing resists the slide (3e-6)
  EXPECT_NEAR(-top_force(slid, 1), normal, 1e-4 * normal);
}

TEST(LargeSliding, SearchingEveryIterationGivesTheSameAnswer) {
  const Results step = run_json(slider(10.0, "large", "direct"));
  const Results every = run_json(slider(10.0, "large_every_iteration", "direct"));
  ASSERT_TRUE(step.status.ok()) << step.status.message;
  ASSERT_TRUE(every.status.ok()) << every.status.message;
  const double normal = step.contacts.at(0).normal_force;
  EXPECT_NEAR(every.contacts.at(0).normal_force, normal, 1e-6 * normal);
}

/// The base's vertical displacement at its top node at x = 18, under the slider's final middle.
double base_dent(const Results& r) { return r.bodies[0].displacement[2 * (36 * 3 + 2) + 1]; }

TEST(LargeSliding, SmallSlidingPressesTheBaseWhereTheSliderStarted) {
  const Results large = run_json(slider(10.0, "large", "direct"));
  const Results small = run_json(slider(10.0, "small", "direct"));
  ASSERT_TRUE(large.status.ok()) << large.status.message;
  ASSERT_TRUE(small.status.ok()) << small.status.message;
  EXPECT_LT(base_dent(large), -2e-3);                               // dented under the slider
  EXPECT_LT(std::abs(base_dent(small)), 1e-2 * -base_dent(large));  // untouched: the rows still act at x ≈ 8
}

INSTANTIATE_TEST_SUITE_P(Modes, LargeSliding, ::testing::Values("direct", "mixed"));

}  // namespace test_large_sliding
