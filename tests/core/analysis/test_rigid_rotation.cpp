// Prescribed rigid rotations inside the Newton analysis: a block turned a quarter turn by one edge follows it
// rigidly and stays unstressed (finite strain), and a stretched block turned by a large rotation carries the same
// stresses, rotated (objectivity). Both through `direct` and through `feti`, whose subdomains inherit the rotation.
#include <gtest/gtest.h>

#include <cmath>

#include "../../common/RunJson.h"

namespace test_rigid_rotation {

using namespace rollsim;
using testing_support::run_json;
using json = nlohmann::json;

namespace {
const double E = 1000, nu = 0.3, L = 10, W = 4;

json block(const json& bcs, const std::string& mode = "direct") {
  json body = {{"name", "block"},
               {"material", "rubberish"},
               {"formulation", "bbar"},
               {"kinematics", "finite"},
               {"mesh", {{"type", "block"}, {"nx", 10}, {"ny", 4}, {"lx", L}, {"ly", W}}}};
  if (mode == "feti") body["partition"] = "2x2";
  return {{"name", "turned"},
          {"dimension", 2},
          {"materials", {{{"name", "rubberish"}, {"E", E}, {"nu", nu}}}},
          {"bodies", {body}},
          {"boundary_conditions", bcs},
          {"analysis", {{"type", "newton"}, {"increments", 8}, {"tolerance", 1e-9}}},
          {"solver", {{"mode", mode}, {"cg_tolerance", 1e-10}}}};
}

json rotation(const std::string& set, double degrees, std::array<double, 2> center, std::array<double, 2> t = {}) {
  return {{"type", "rotation"}, {"body", "block"}, {"set", set}, {"center", center},
          {"angle", degrees},   {"ux", t[0]},      {"uy", t[1]}};
}

double max_abs(const std::vector<std::array<double, 6>>& s) {
  double m = 0;
  for (const auto& e : s)
    for (double v : e) m = std::max(m, std::abs(v));
  return m;
}
}  // namespace

class PrescribedRotation : public ::testing::TestWithParam<std::string> {};

TEST_P(PrescribedRotation, AQuarterTurnByOneEdgeIsRigidAndUnstressed) {
  const Results r = run_json(block(json::array({rotation("xmin", 90.0, {0.0, W / 2})}), GetParam()));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.increments.size(), 8u);
  // the far corner (L, 0) goes to (W/2, W/2 + L): u = (W/2 − L, W/2 + L − 0)
  const Eigen::VectorXd& u = r.bodies[0].displacement;
  const Eigen::Index corner = 2 * (10 * 5);  // node (i = 10, j = 0): numbered along y first
  EXPECT_NEAR(u[corner], W / 2 - L, 1e-8 * L);
  EXPECT_NEAR(u[corner + 1], W / 2 + L, 1e-8 * L);
  EXPECT_LT(max_abs(r.bodies[0].element_stress), 1e-8 * E);
}

TEST_P(PrescribedRotation, AStretchedBlockTurnedCarriesTheSameStressesRotated) {
  const double stretch = 1.5, theta = 70.0, c = std::cos(theta * M_PI / 180), s = std::sin(theta * M_PI / 180);
  const Results plain = run_json(
      block({rotation("xmin", 0.0, {0.0, 0.0}), rotation("xmax", 0.0, {0.0, 0.0}, {stretch, 0.0})}, GetParam()));
  const Results turned = run_json(
      block({rotation("xmin", theta, {0.0, 0.0}), rotation("xmax", theta, {0.0, 0.0}, {c * stretch, s * stretch})},
            GetParam()));
  ASSERT_TRUE(plain.status.ok()) << plain.status.message;
  ASSERT_TRUE(turned.status.ok()) << turned.status.message;
  const auto &a = plain.bodies[0].element_stress, &b = turned.bodies[0].element_stress;
  ASSERT_EQ(a.size(), b.size());
  const double scale = max_abs(a);
  EXPECT_GT(scale, 10.0);  // 15 % stretch of E = 1000: stresses of order 100
  for (size_t e = 0; e < a.size(); ++e) {
    const double xx = a[e][0], yy = a[e][1], xy = a[e][3];  // R σ Rᵀ
    EXPECT_NEAR(b[e][0], c * c * xx - 2 * c * s * xy + s * s * yy, 1e-7 * scale) << "element " << e;
    EXPECT_NEAR(b[e][1], s * s * xx + 2 * c * s * xy + c * c * yy, 1e-7 * scale) << "element " << e;
    EXPECT_NEAR(b[e][3], c * s * (xx - yy) + (c * c - s * s) * xy, 1e-7 * scale) << "element " << e;
    EXPECT_NEAR(b[e][2], a[e][2], 1e-7 * scale) << "element " << e;  // σ_zz (plane strain)
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, PrescribedRotation, ::testing::Values("direct", "feti"));

}  // namespace test_rigid_rotation
