// The material interface: make_material builds the behaviour from the model's plain MaterialData; LinearElastic
// returns σ = C ε with Hooke's constants and a symmetric positive definite tangent, keeps no state, and its
// uniaxial-stress response has Young's modulus E and Poisson's ratio ν.
#include <gtest/gtest.h>

#include "material/LinearElastic.h"

namespace test_material {

using namespace rollsim;

TEST(Material, MadeFromPlainDataIsLinearElasticWithoutState) {
  const auto m = make_material(MaterialData{210e3, 0.3});
  EXPECT_EQ(m->name(), "linear_elastic");
  EXPECT_EQ(m->state_size(), 0);
  const Tangent6 C = m->initial_tangent();
  EXPECT_LT((C - C.transpose()).norm(), 1e-12 * C.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Tangent6>(C).eigenvalues().minCoeff(), 0.0);
}

TEST(Material, UniaxialStressRecoversEAndNu) {
  const double E = 210e3, nu = 0.3;
  const auto m = make_material(MaterialData{E, nu});
  Deformation d;  // the strain of a uniaxial stress σ_xx = 100
  d.strain << 100 / E, -nu * 100 / E, -nu * 100 / E, 0, 0, 0;
  Voigt6 stress;
  Tangent6 tangent;
  m->update(d, nullptr, nullptr, stress, tangent);
  EXPECT_NEAR(stress(0), 100.0, 1e-9);
  EXPECT_NEAR(stress.tail<5>().norm(), 0.0, 1e-9);
  d.strain << 0, 0, 0, 2e-3, 0, 0;  // engineering shear γ_xy: τ = G γ
  m->update(d, nullptr, nullptr, stress, tangent);
  EXPECT_NEAR(stress(3), E / (2 * (1 + nu)) * 2e-3, 1e-9);
  EXPECT_EQ(tangent, LinearElastic(E, nu).tangent3d());
}

TEST(Material, VonMisesOfUniaxialAndPureShear) {
  const double uniaxial[6] = {100, 0, 0, 0, 0, 0}, shear[6] = {0, 0, 0, 50, 0, 0};
  EXPECT_NEAR(von_mises(uniaxial), 100.0, 1e-12);
  EXPECT_NEAR(von_mises(shear), 50.0 * std::sqrt(3.0), 1e-12);
}

}  // namespace test_material
