// analysis.contact_tangent: the contact's geometric stiffness in Newton's tangent. A block pressed on a base and pushed
// along it by 20 segments, searched at every iteration (large_every_iteration): every solver mode takes the same
// Newton iterations per step (±1) for the same variant and reaches the same normal force; `full` (the slave–master
// terms too) needs one global matrix and is refused by the others.
#include <gtest/gtest.h>

#include "../../common/RunJson.h"
#include "analysis/AnalysisError.h"

using namespace rollsim;
using testing_support::run_json;
using json = nlohmann::json;

namespace {
json slider(const std::string& mode, const std::string& tangent) {
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
         {"sliding", "large_every_iteration"}}}},
      {"boundary_conditions",
       {{{"type", "displacement"}, {"body", "base"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
        {{"type", "displacement"}, {"body", "slider"}, {"set", "ymax"}, {"ux", 10.0}, {"uy", -0.02}}}},
      {"analysis", {{"type", "newton"}, {"increments", 20}, {"tolerance", 1e-9}, {"contact_tangent", tangent}}},
      {"solver", {{"mode", mode}, {"cg_tolerance", 1e-10}}}};
}

int total_iterations(const Results& r) {
  int n = 0;
  for (const IncrementResults& inc : r.increments) n += inc.newton_iterations;
  return n;
}

/// Both converged through the same steps, each step's Newton iterations within one, the same normal force.
void expect_same_path(const Results& a, const Results& b) {
  ASSERT_TRUE(a.status.ok()) << a.status.message;
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  ASSERT_EQ(a.increments.size(), b.increments.size());
  for (size_t i = 0; i < a.increments.size(); ++i)
    EXPECT_LE(std::abs(a.increments[i].newton_iterations - b.increments[i].newton_iterations), 1) << "step " << i + 1;
  const double normal = a.contacts.at(0).normal_force;
  EXPECT_NEAR(b.contacts.at(0).normal_force, normal, 1e-6 * normal);
}
}  // namespace

class ContactTangentModes : public ::testing::TestWithParam<std::string> {};

TEST_P(ContactTangentModes, EveryModeTakesTheSameNewtonIterationsAsDirect) {
  const Results direct = run_json(slider("direct", GetParam()));
  for (const char* mode : {"mixed", "skyline"}) {
    SCOPED_TRACE(mode);
    expect_same_path(direct, run_json(slider(mode, GetParam())));
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, ContactTangentModes, ::testing::Values("none", "groups"));

TEST(ContactTangent, TheVariantsReachTheSameAnswer) {
  const Results none = run_json(slider("direct", "none"));
  const Results groups = run_json(slider("direct", "groups"));
  const Results full = run_json(slider("direct", "full"));
  for (const Results* r : {&none, &groups, &full}) ASSERT_TRUE(r->status.ok()) << r->status.message;
  const double normal = none.contacts.at(0).normal_force;
  EXPECT_NEAR(groups.contacts.at(0).normal_force, normal, 1e-6 * normal);
  EXPECT_NEAR(full.contacts.at(0).normal_force, normal, 1e-6 * normal);
  EXPECT_LT(total_iterations(full), total_iterations(none));  // the whole term: Newton converges quadratically
}

TEST(ContactTangent, FullIsRefusedWithoutAGlobalMatrix) {
  EXPECT_THROW(run_json(slider("mixed", "full")), AnalysisError);
}
