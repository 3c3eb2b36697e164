// Coulomb friction (the issue's check): a block pressed on a (much stiffer) plane and dragged along it by two of the
// plane's segments carries exactly μ times its normal force once it slips, and less while it sticks; a sticking pair
// holds beyond μ N. The same answers from `direct` and `mixed` (the friction force acts on the bodies' residuals, the
// stiffness blocks stay symmetric).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "../../common/RunJson.h"

namespace test_friction {

using namespace rollsim;
using testing_support::run_json;
using json = nlohmann::json;

namespace {
const double mu = 0.3;

/// `mode`: a solver mode, or "mixed+dense" (mixed with its interface formed and factored, unsymmetric when slipping)
json drag(double distance, const std::string& type, const std::string& mode) {
  auto block = [](const std::string& name, json mesh) {
    return json{{"name", name}, {"material", name}, {"kinematics", "finite"}, {"mesh", mesh}};
  };
  json pair = {{"name", "drag"},          {"type", type},           {"slave_body", "block"},
               {"slave_surface", "ymin"}, {"master_body", "plane"}, {"master_surface", "ymax"},
               {"search_distance", 0.2},  {"sliding", "large"}};
  if (type == "coulomb") pair["friction"] = mu;
  return {
      {"name", "drag"},
      {"dimension", 2},
      {"materials", {{{"name", "block"}, {"E", 1000.0}, {"nu", 0.3}}, {{"name", "plane"}, {"E", 1e6}, {"nu", 0.3}}}},
      {"bodies",
       {block("plane", {{"type", "block"}, {"nx", 20}, {"ny", 2}, {"lx", 10.0}, {"ly", 1.0}}),
        block("block", {{"type", "block"}, {"nx", 4}, {"ny", 2}, {"lx", 2.0}, {"ly", 1.0}, {"origin", {3.0, 1.0}}})}},
      {"contacts", {pair}},
      {"boundary_conditions",
       {{{"type", "displacement"}, {"body", "plane"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
        {{"type", "displacement"}, {"body", "block"}, {"set", "ymax"}, {"ux", distance}, {"uy", -0.01}}}},
      {"analysis", {{"type", "newton"}, {"increments", 10}, {"tolerance", 1e-9}, {"max_iterations", 60}}},
      {"solver",
       {{"mode", mode == "mixed+dense" ? "mixed" : mode},
        {"interface_solver", mode == "mixed+dense" ? "dense" : "krylov"},
        {"cg_tolerance", 1e-10}}}};
}

/// The force that drags and presses the block: the reaction of its top (uy = −0.01), component k.
double top_force(const Results& r, int k) { return testing_support::reaction_where_uy(r, 1, 2, -0.01, k); }
}  // namespace

class Friction : public ::testing::TestWithParam<std::string> {};

TEST_P(Friction, ASlidingBlockCarriesExactlyMuTimesItsNormalForce) {
  const Results r = run_json(drag(1.0, "coulomb", GetParam()));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double pressing = -top_force(r, 1), dragging = top_force(r, 0);
  EXPECT_GT(pressing, 1.0);
  // at every point (the contact's own resultants) to the Newton tolerance; through the drag's reactions to the
  // tilt of the normals on the (stiff) plane
  EXPECT_NEAR(r.contacts.at(0).tangential_force, mu * r.contacts.at(0).normal_force, 1e-6 * pressing);
  EXPECT_NEAR(dragging, mu * pressing, 1e-4 * pressing);
  // the slip field: every node of the block's bottom slid the drag less the block's shear (μ p h / G ≈ 0.01)
  const Eigen::VectorXd& slip = r.bodies[1].contact_slip;
  ASSERT_EQ(slip.size(), 15);
  for (int n = 0; n < 15; n += 3) {  // the bottom nodes: numbered along y first, 3 per column
    EXPECT_GT(slip[n], 0.97) << "node " << n;
    EXPECT_LT(slip[n], 1.0) << "node " << n;
  }
}

TEST_P(Friction, ABlockDraggedLessThanItsSlipDistanceSticksBelowMuN) {
  const Results r = run_json(drag(0.004, "coulomb", GetParam()));
  const Results stuck = run_json(drag(0.004, "sticking", GetParam()));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(stuck.status.ok()) << stuck.status.message;
  const double pressing = -top_force(r, 1), dragging = top_force(r, 0);
  EXPECT_GT(dragging, 0.1 * mu * pressing);  // friction holds it back...
  EXPECT_LT(dragging, 0.9 * mu * pressing);  // ...below the limit,
  // ...and close to a sticking pair's: only the block's edges, where the shear concentrates, slip (partial slip,
  // Cattaneo–Mindlin; measured 2.761 against 2.835)
  EXPECT_LT(dragging, top_force(stuck, 0));
  EXPECT_GT(dragging, 0.9 * top_force(stuck, 0));
}

TEST_P(Friction, AStickingPairHoldsBeyondMuN) {
  const Results stuck = run_json(drag(1.0, "sticking", GetParam()));
  ASSERT_TRUE(stuck.status.ok()) << stuck.status.message;
  EXPECT_GT(top_force(stuck, 0), 2 * mu * -top_force(stuck, 1));
  EXPECT_LT(stuck.bodies[1].contact_slip.cwiseAbs().maxCoeff(), 1e-9) << "nothing slides";
}

TEST_P(Friction, AShearLimitCapsTheFrictionStressAtItsValueTimesTheContactLength) {
  // Tresca's cap on a sticking pair (a rolling slab's τ ≤ k): once dragged, every point slips with shear_limit × its
  // tributary length — the block's bottom, 2.0 long and 0.4 % longer where the pressed block spreads — whatever the
  // normal force; a Coulomb pair takes the smaller
  const double tau = 0.4;
  json p = drag(1.0, "sticking", GetParam());
  p["contacts"][0]["shear_limit"] = tau;
  const Results r = run_json(p);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double length = r.contacts.at(0).measure;
  EXPECT_NEAR(length, 2.0, 0.01);
  EXPECT_NEAR(r.contacts.at(0).tangential_force, tau * length, 1e-9);
  EXPECT_LT(tau * 2.0, mu * r.contacts.at(0).normal_force);  // below what μ = 0.3 would carry...
  json c = drag(1.0, "coulomb", GetParam());
  c["contacts"][0]["shear_limit"] = tau;
  const Results capped = run_json(c);
  ASSERT_TRUE(capped.status.ok()) << capped.status.message;
  EXPECT_NEAR(capped.contacts.at(0).tangential_force, tau * capped.contacts.at(0).measure,
              1e-9);  // ...so the cap rules the Coulomb pair too
}

INSTANTIATE_TEST_SUITE_P(Modes, Friction, ::testing::Values("direct", "mixed", "mixed+dense"),
                         [](const auto& info) { return info.param == "mixed+dense" ? "mixed_dense" : info.param; });

class FrictionTangentTest : public ::testing::TestWithParam<std::string> {};

TEST_P(FrictionTangentTest, TheConsistentTangentReachesTheSameSlidingForceInFewerIterations) {
  // the sliding block: with the friction force μ λ_n solved for with λ_n (an unsymmetric system: UMFPACK under direct,
  // projected GMRES on the interface under mixed and feti) Newton converges quadratically once the stick/slip set
  // holds; lagged one iteration behind λ_n it converges linearly
  auto run = [](const std::string& tangent) {
    json p = drag(1.0, "coulomb", GetParam());
    p["analysis"]["friction_tangent"] = tangent;
    if (GetParam() == "feti") p["bodies"][0]["partition"] = "2x1";  // the plane torn: C_eq split over subdomains
    return run_json(p);
  };
  const Results consistent = run("consistent"), lagged = run("lagged");
  ASSERT_TRUE(consistent.status.ok()) << consistent.status.message;
  ASSERT_TRUE(lagged.status.ok()) << lagged.status.message;
  const double n = consistent.contacts.at(0).normal_force;
  EXPECT_NEAR(consistent.contacts.at(0).tangential_force, lagged.contacts.at(0).tangential_force, 1e-6 * n);
  EXPECT_NEAR(n, lagged.contacts.at(0).normal_force, 1e-6 * n);
  EXPECT_LT(consistent.newton.size() * 3, lagged.newton.size() * 2)
      << consistent.newton.size() << " iterations against " << lagged.newton.size();
}

INSTANTIATE_TEST_SUITE_P(Modes, FrictionTangentTest, ::testing::Values("direct", "mixed", "feti"));

TEST(FrictionInput, BadFrictionIsRefusedWithItsPath) {
  struct Case {
    std::string what, path;
    std::function<void(json&)> edit;
  };
  const std::vector<Case> cases = {
      {"negative μ", "contacts[0].friction", [](json& p) { p["contacts"][0]["friction"] = -0.1; }},
      {"coulomb without μ", "contacts[0].friction", [](json& p) { p["contacts"][0].erase("friction"); }},
      {"μ on a frictionless pair", "contacts[0].friction", [](json& p) { p["contacts"][0]["type"] = "frictionless"; }},
      {"friction in a linear analysis", "analysis.type", [](json& p) { p["analysis"]["type"] = "linear"; }},
      {"a shear limit on a frictionless pair", "contacts[0].shear_limit",
       [](json& p) {
         p["contacts"][0]["type"] = "frictionless";
         p["contacts"][0].erase("friction");
         p["contacts"][0]["shear_limit"] = 1.0;
       }},
      {"a negative shear limit", "contacts[0].shear_limit", [](json& p) { p["contacts"][0]["shear_limit"] = -1.0; }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    json p = drag(1.0, "coulomb", "direct");
    c.edit(p);
    try {
      const Project project = parse_project(p.dump(), "test.json");
      build_model(project);
      ADD_FAILURE() << "accepted";
    } catch (const ProjectError& e) {
      ASSERT_FALSE(e.issues().empty());
      EXPECT_EQ(e.issues()[0].path, c.path) << e.what();
    }
  }
}

TEST(Friction3D, ABlockSlidingOnAFaceCarriesMuN) {
  // the same drag in 3D, diagonally (x and z), node-to-face: the friction force lies in the face's plane and opposes
  // the slip, whatever the tangents of the face are
  json p = drag(0.0, "coulomb", "direct");
  p["dimension"] = 3;
  p["bodies"][0]["mesh"].update({{"nx", 10}, {"nz", 4}, {"lz", 4.0}});
  p["bodies"][1]["mesh"].update({{"nx", 2}, {"nz", 2}, {"lz", 2.0}, {"origin", {3.0, 1.0, 1.0}}});
  p["boundary_conditions"][0]["uz"] = 0.0;
  p["boundary_conditions"][1].update({{"ux", 0.6}, {"uz", 0.3}});
  const Results r = run_json(p);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const ContactResult& c = r.contacts.at(0);
  EXPECT_GT(c.normal_force, 1.0);
  // |Σ f_t| ≤ Σ μ N_j: each point slips along its own relative motion, which the block's lateral expansion turns
  // slightly (measured 13.53606 against 13.53616)
  EXPECT_NEAR(c.tangential_force, mu * c.normal_force, 1e-4 * c.normal_force);
  // the drag's reactions point along the drag: x : z = 2 : 1
  const double fx = testing_support::reaction_where_uy(r, 1, 3, -0.01, 0);
  const double fz = testing_support::reaction_where_uy(r, 1, 3, -0.01, 2);
  EXPECT_NEAR(fz / fx, 0.5, 1e-3);
}

}  // namespace test_friction
