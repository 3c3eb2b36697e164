// Coulomb friction in 3D (issue 38 (b)): a 1 × 1 × 0.5 block pressed 0.02 into a 4 × 4 × 1 base of the same
// stiffness and dragged 0.6 × 0.3 over it in 5 steps. The base deforms under the block, so the slip directions turn
// with the displacements of both bodies: the friction direction's stiffness K_d = (F/|v|) R̃ᵀ w wᵀ R̃ joins the
// block (slave) and the base (master). Under contact_tangent `groups` its slave–master part used to be dropped —
// `direct` and `mixed` then took 13, 13, 17 Newton iterations over the sliding steps 3–5, against 9, 8, 11 with
// `full`, and on the 3D rolling pass Newton stalled (docs/BENCHMARKS-ROLLING.md, "Coulomb friction in 3D"). Now
// `direct` takes it into its global matrix and `mixed` as compliant interface rows (BlockSystem::compliance): both
// match `full`. Every point slides: the contact carries μ N, each point's force along its trial force (contact/
// Friction.h), against its slip once it has slid far against the elastic slip.
#include <gtest/gtest.h>

#include "../../common/RunJson.h"
#include "solve/MixedStrategy.h"

namespace test_friction_3d {

using namespace rollsim;
using testing_support::run_json;
using json = nlohmann::json;

namespace {
json drag_3d(const std::string& mode, const std::string& contact_tangent) {
  auto body = [](const std::string& name, json mesh) {
    return json{{"name", name}, {"material", "m"}, {"kinematics", "finite"}, {"mesh", mesh}};
  };
  return {{"name", "drag-3d"},
          {"dimension", 3},
          {"materials", {{{"name", "m"}, {"E", 1000.0}, {"nu", 0.3}}}},
          {"bodies",
           {body("base", {{"type", "block"},
                          {"nx", 4},
                          {"ny", 4},
                          {"nz", 1},
                          {"lx", 4.0},
                          {"ly", 4.0},
                          {"lz", 1.0},
                          {"origin", {0.0, 0.0, -1.0}}}),
            body("block", {{"type", "block"},
                           {"nx", 2},
                           {"ny", 2},
                           {"nz", 1},
                           {"lx", 1.0},
                           {"ly", 1.0},
                           {"lz", 0.5},
                           {"origin", {1.45, 1.55, 0.0}}})}},
          {"contacts",
           {{{"name", "drag"},
             {"type", "coulomb"},
             {"friction", 0.3},
             {"slave_body", "block"},
             {"slave_surface", "zmin"},
             {"master_body", "base"},
             {"master_surface", "zmax"},
             {"search_distance", 0.2},
             {"sliding", "large"}}}},
          {"boundary_conditions",
           {{{"type", "displacement"}, {"body", "base"}, {"set", "zmin"}, {"ux", 0.0}, {"uy", 0.0}, {"uz", 0.0}},
            {{"type", "displacement"}, {"body", "block"}, {"set", "zmax"}, {"ux", 0.6}, {"uy", 0.3}, {"uz", -0.02}}}},
          {"analysis", {{"type", "newton"}, {"increments", 5}, {"contact_tangent", contact_tangent}}},
          {"solver", {{"mode", mode}, {"cg_tolerance", 1e-10}}}};
}
}  // namespace

class Friction3d : public ::testing::TestWithParam<std::string> {};

TEST_P(Friction3d, TheSlipDirectionsTurnWithTheWholeTangentUnderGroups) {
  const Results r = run_json(drag_3d(GetParam(), "groups"));
  const Results full = run_json(drag_3d("direct", "full"));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(full.status.ok()) << full.status.message;
  const ContactResult& c = r.contacts.at(0);
  // all slide: μ N to the tilt of the base's normals under the block (0.3 × 0.99997)
  EXPECT_NEAR(c.tangential_force, 0.3 * c.normal_force, 1e-4 * c.normal_force);
  EXPECT_NEAR(c.normal_force, full.contacts.at(0).normal_force, 1e-6 * c.normal_force);
  ASSERT_EQ(r.increments.size(), 5u);
  ASSERT_EQ(full.increments.size(), 5u);
  for (size_t i = 2; i < 5; ++i) {  // the sliding steps: the slab–roll part of K_d counts there (was 13, 13, 17)
    EXPECT_LE(r.increments[i].newton_iterations, full.increments[i].newton_iterations + 1) << "step " << i + 1;
    EXPECT_LE(r.increments[i].newton_iterations, 12) << "step " << i + 1;
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, Friction3d, ::testing::Values("direct", "mixed"));

TEST(MixedCompliance, ACompliantRowActsAsTheStiffnessItStandsFor) {
  // two springs to ground, 2 and 3, joined by a third, k = 5, written as the row c = [1, −1] with compliance 1/k:
  // u = [[7, −5], [−5, 8]]⁻¹ [1, 0] = [8, 5] / 31
  auto group = [](const std::string& name, double k, double f) {
    Group g;
    g.name = name;
    g.K = SparseMatrix(1, 1);
    g.K.insert(0, 0) = k;
    g.f = Eigen::VectorXd::Constant(1, f);
    g.C = SparseMatrix(0, 1);
    g.R.resize(1, 0);
    return g;
  };
  BlockSystem sys;
  sys.groups = {group("A", 2, 1), group("B", 3, 0)};
  sys.d = Eigen::VectorXd(0);
  sys.groups[0].C_compliant = SparseMatrix(1, 1);
  sys.groups[0].C_compliant.insert(0, 0) = 1;
  sys.groups[1].C_compliant = SparseMatrix(1, 1);
  sys.groups[1].C_compliant.insert(0, 0) = -1;
  sys.compliance = Eigen::VectorXd::Constant(1, 1.0 / 5);
  SolverOptions o;
  o.cg_tolerance = 1e-12;
  MixedStrategy mixed(o);
  ASSERT_TRUE(mixed.solves_compliant());
  const BlockSolution s = mixed.solve(sys);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  EXPECT_EQ(s.lambda.size(), 0);  // the compliant rows' multipliers stay inside
  EXPECT_NEAR(s.u[0][0], 8.0 / 31, 1e-10);
  EXPECT_NEAR(s.u[1][0], 5.0 / 31, 1e-10);
}

}  // namespace test_friction_3d
