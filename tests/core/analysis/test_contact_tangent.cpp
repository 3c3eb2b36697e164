// analysis.contact_tangent: the contact's geometric stiffness in Newton's tangent. A block pressed on a base and pushed
// along it by 20 segments (2D) or 10 faces (3D), searched at every iteration (large_every_iteration): every solver mode
// takes the same Newton iterations per step (±1) for the same variant and reaches the same normal force; `full` (the
// slave–master terms too) needs one global matrix and is refused by the others.
#include <gtest/gtest.h>

#include <tuple>

#include "../../common/RunJson.h"
#include "analysis/AnalysisError.h"

namespace test_contact_tangent {

using namespace rollsim;
using testing_support::run_json;
using json = nlohmann::json;

namespace {
json block(const std::string& name, json mesh) {
  return json{{"name", name}, {"material", name}, {"kinematics", "finite"}, {"mesh", mesh}};
}

/// 2D: a 1.5 × 1 block pushed 10 along a 30 × 2 base of 0.5 segments. 3D: a 1.5 × 1.5 × 1 block pushed 5 along a
/// 12 × 3 × 1 base of 0.5 × 1 faces, its nodes off the faces' edges across the push.
json slider(int dim, const std::string& mode, const std::string& tangent) {
  const bool two = dim == 2;
  const json base =
      two ? json{{"type", "block"}, {"nx", 60}, {"ny", 2}, {"lx", 30.0}, {"ly", 2.0}}
          : json{{"type", "block"}, {"nx", 24}, {"ny", 3}, {"nz", 1}, {"lx", 12.0}, {"ly", 3.0}, {"lz", 1.0}};
  const json slider =
      two ? json{{"type", "block"}, {"nx", 3}, {"ny", 2}, {"lx", 1.5}, {"ly", 1.0}, {"origin", {7.25, 2.0}}}
          : json{{"type", "block"}, {"nx", 3},   {"ny", 2},   {"nz", 1},
                 {"lx", 1.5},       {"ly", 1.5}, {"lz", 1.0}, {"origin", {3.25, 0.75, 1.0}}};
  const std::string bottom = two ? "ymin" : "zmin", top = two ? "ymax" : "zmax";
  json fixed = {{"type", "displacement"}, {"body", "base"}, {"set", bottom}, {"ux", 0.0}, {"uy", 0.0}};
  json pushed = {{"type", "displacement"}, {"body", "slider"}, {"set", top}, {"ux", two ? 10.0 : 5.0}};
  if (two) {
    pushed["uy"] = -0.02;
  } else {
    fixed["uz"] = 0.0;
    pushed["uy"] = 0.0, pushed["uz"] = -0.02;
  }
  return {
      {"name", "slider"},
      {"dimension", dim},
      {"materials", {{{"name", "base"}, {"E", 1000.0}, {"nu", 0.3}}, {{"name", "slider"}, {"E", 2000.0}, {"nu", 0.3}}}},
      {"bodies", {block("base", base), block("slider", slider)}},
      {"contacts",
       {{{"name", "slide"},
         {"type", "frictionless"},
         {"slave_body", "slider"},
         {"slave_surface", bottom},
         {"master_body", "base"},
         {"master_surface", top},
         {"search_distance", 0.2},
         {"sliding", "large_every_iteration"}}}},
      {"boundary_conditions", {fixed, pushed}},
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

class ContactTangentModes : public ::testing::TestWithParam<std::tuple<int, std::string>> {};

TEST_P(ContactTangentModes, EveryModeTakesTheSameNewtonIterationsAsDirect) {
  const auto [dim, tangent] = GetParam();
  const Results direct = run_json(slider(dim, "direct", tangent));
  for (const char* mode : {"mixed", "skyline"}) {
    SCOPED_TRACE(mode);
    expect_same_path(direct, run_json(slider(dim, mode, tangent)));
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, ContactTangentModes,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Values("none", "groups")));

class ContactTangentVariants : public ::testing::TestWithParam<int> {};

TEST_P(ContactTangentVariants, TheVariantsReachTheSameAnswer) {
  const Results none = run_json(slider(GetParam(), "direct", "none"));
  const Results groups = run_json(slider(GetParam(), "direct", "groups"));
  const Results full = run_json(slider(GetParam(), "direct", "full"));
  for (const Results* r : {&none, &groups, &full}) ASSERT_TRUE(r->status.ok()) << r->status.message;
  const double normal = none.contacts.at(0).normal_force;
  EXPECT_NEAR(groups.contacts.at(0).normal_force, normal, 1e-6 * normal);
  EXPECT_NEAR(full.contacts.at(0).normal_force, normal, 1e-6 * normal);
  EXPECT_LT(total_iterations(full), total_iterations(none));  // the whole term: Newton converges quadratically
}

INSTANTIATE_TEST_SUITE_P(Dimensions, ContactTangentVariants, ::testing::Values(2, 3));

TEST(ContactTangent, FullIsRefusedWithoutAGlobalMatrix) {
  EXPECT_THROW(run_json(slider(2, "mixed", "full")), AnalysisError);
}

}  // namespace test_contact_tangent
