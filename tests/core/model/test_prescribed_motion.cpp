// Prescribed rigid rotations: Rodrigues' formula against hand-computed rotations, the dof map's values at a load
// factor (the angle grows with it, exact at any angle), and a subdomain's map restricted from its body's.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/StructuredBlock.h"
#include "model/DofMap.h"
#include "model/PrescribedMotion.h"

namespace test_prescribed_motion {

using namespace rollsim;

TEST(PrescribedMotion, QuarterTurnAboutZ) {
  const RigidRotation r{{1.0, 1.0, 0.0}, {0.0, 0.0, 1.0}, M_PI / 2};
  const auto u = rotation_displacement(r, {2.0, 1.0, 0.0}, 1.0);  // (1, 0) about (1, 1) goes to (0, 1)
  EXPECT_NEAR(u[0], -1.0, 1e-15);
  EXPECT_NEAR(u[1], 1.0, 1e-15);
  EXPECT_EQ(u[2], 0.0);
  const auto half = rotation_displacement(r, {2.0, 1.0, 0.0}, 0.5);  // 45°: (cos − 1, sin)
  EXPECT_NEAR(half[0], std::sqrt(0.5) - 1.0, 1e-15);
  EXPECT_NEAR(half[1], std::sqrt(0.5), 1e-15);
}

TEST(PrescribedMotion, ThreeDimensionalAxisKeepsDistancesAndAxialPosition) {
  const double k = 1 / std::sqrt(3.0);
  const RigidRotation r{{0.5, -1.0, 2.0}, {k, k, k}, 2.0};
  const std::array<double, 3> X{3.0, 1.0, -2.0};
  const auto u = rotation_displacement(r, X, 0.7);
  Eigen::Vector3d c(0.5, -1.0, 2.0), a(k, k, k), x(X[0], X[1], X[2]), y = x + Eigen::Vector3d(u[0], u[1], u[2]);
  EXPECT_NEAR((y - c).norm(), (x - c).norm(), 1e-13);
  EXPECT_NEAR((y - c).dot(a), (x - c).dot(a), 1e-13);  // a rotation does not move along its axis
  // the angle between the radial parts is 0.7 × 2 rad
  const Eigen::Vector3d px = (x - c) - (x - c).dot(a) * a, py = (y - c) - (y - c).dot(a) * a;
  EXPECT_NEAR(std::acos(px.dot(py) / (px.norm() * py.norm())), 1.4, 1e-12);
  EXPECT_GT(px.cross(py).dot(a), 0);  // right-hand rule
  // three full turns bring every point back
  const auto back = rotation_displacement(RigidRotation{r.center, r.axis, 6 * M_PI}, X, 1.0);
  for (double v : back) EXPECT_NEAR(v, 0.0, 1e-13);
}

TEST(PrescribedMotion, ConditionValuesTranslationAndRotation) {
  DisplacementBC plain{0, "s", {0}, {0.25, std::nullopt, std::nullopt}, 0, std::nullopt};
  EXPECT_EQ(prescribed_value(plain, {1, 2, 0}, 0, 0.5), 0.125);
  EXPECT_FALSE(prescribed_value(plain, {1, 2, 0}, 1, 0.5));  // a free component
  DisplacementBC turned = plain;
  turned.rotation = RigidRotation{{0, 0, 0}, {0, 0, 1}, M_PI};
  EXPECT_NEAR(*prescribed_value(turned, {1, 2, 0}, 0, 1.0), -2.0 + 0.25, 1e-15);
  EXPECT_NEAR(*prescribed_value(turned, {1, 2, 0}, 1, 1.0), -4.0, 1e-15);  // every component is prescribed
}

TEST(DofMapRotation, ValuesFollowTheAngleAndSubdomainsInheritThem) {
  Body body;
  body.mesh = make_block({2, {4, 2, 1}, {4.0, 2.0, 1.0}});
  const std::vector<int> left = body.mesh.node_sets.at("xmin");
  DisplacementBC hub{0, "xmin", left, {}, 0, RigidRotation{{0.0, 1.0, 0.0}, {0, 0, 1}, M_PI / 3}};
  DisplacementBC roller{0, "ymin", body.mesh.node_sets.at("ymin"), {std::nullopt, 0.1, std::nullopt}, 1, {}};
  const DofMap map(body, 0, {roller, hub});
  EXPECT_EQ(map.num_prescribed(), 2 * 3 + 4);  // the three left nodes both ways, the four other bottom nodes in y
  for (int n : left)
    for (double lf : {0.25, 1.0}) {
      const auto u = rotation_displacement(hub.rotation.value(), body.mesh.nodes[n], lf);
      EXPECT_EQ(map.prescribed(n, 0, lf), u[0]);
      EXPECT_EQ(map.prescribed(n, 1, lf), u[1]);
    }
  const Eigen::VectorXd full = map.expand(Eigen::VectorXd::Zero(map.num_free()), 0.5);
  EXPECT_EQ(full[2 * 3 + 1], 0.05);  // node 3 (bottom, x = 1): the roller's translation at half load
  // a part of the body: nodes 0 (rotated), 3 (roller) and 4 (free)
  const std::vector<int> part{0, 3, 4};
  const DofMap sub(map, part);
  EXPECT_EQ(sub.num_free(), 2 + 1);
  for (size_t l = 0; l < part.size(); ++l)
    for (int c = 0; c < 2; ++c) {
      EXPECT_EQ(sub.equation(static_cast<int>(l), c) < 0, map.equation(part[l], c) < 0);
      EXPECT_EQ(sub.prescribed(static_cast<int>(l), c, 0.3), map.prescribed(part[l], c, 0.3));
    }
}

}  // namespace test_prescribed_motion
