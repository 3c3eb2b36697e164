// The closed-form spatial modulus dτ/d(∇_x u) equals central differences of the finite-strain update τ((I + h E) F)
// for Hencky elasticity and for J2's exponential map at a plastic state, also where b has repeated eigenvalues (the
// divided differences of ln meet its derivative there); the divided difference of ln is accurate for close arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../common/SaturatingSteel.h"
#include "material/KirchhoffModulus.h"

namespace test_kirchhoff_modulus {

using namespace rollsim;

namespace {
MaterialData plastic() { return rollsim::testing::saturating_steel(); }

/// τ at F from a committed state of zeros (the update's own trial state is discarded).
Voigt6 kirchhoff(const Material& mat, const Eigen::Matrix3d& F, FiniteTangent* tangent = nullptr) {
  std::vector<double> committed(static_cast<size_t>(mat.state_size()), 0.0), trial(committed.size());
  Voigt6 tau;
  mat.update_finite(F, committed.data(), trial.data(), tau, tangent);
  return tau;
}

/// Largest entry of (closed form − central differences), relative to the largest entry of the closed form.
double modulus_error(const MaterialData& data, const Eigen::Matrix3d& F) {
  const auto mat = make_material(data);
  FiniteTangent t;
  kirchhoff(*mat, F, &t);
  const Eigen::Matrix<double, 9, 9> A = kirchhoff_modulus(t);
  Eigen::Matrix<double, 9, 9> fd;
  const double h = 1e-7;
  for (int m = 0; m < 3; ++m)
    for (int l = 0; l < 3; ++l) {
      Eigen::Matrix3d E = Eigen::Matrix3d::Zero();
      E(m, l) = h;
      const Eigen::Matrix3d plus = stress_tensor(kirchhoff(*mat, (Eigen::Matrix3d::Identity() + E) * F));
      const Eigen::Matrix3d minus = stress_tensor(kirchhoff(*mat, (Eigen::Matrix3d::Identity() - E) * F));
      const Eigen::Matrix3d d = (plus - minus) / (2 * h);
      fd.col(m * 3 + l) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(d.data());
    }
  return (A - fd).cwiseAbs().maxCoeff() / A.cwiseAbs().maxCoeff();
}

Eigen::Matrix3d general_stretch() {
  Eigen::Matrix3d F;
  F << 1.12, 0.07, -0.03, 0.02, 0.93, 0.05, -0.04, 0.06, 1.01;
  return F;
}
}  // namespace

TEST(KirchhoffModulus, EqualsCentralDifferencesOfHenckyElasticity) {
  const MaterialData elastic{200e3, 0.3};
  EXPECT_LT(modulus_error(elastic, general_stretch()), 1e-6);
  EXPECT_LT(modulus_error(elastic, Eigen::Matrix3d::Identity()), 1e-6);  // b = I: all three eigenvalues equal
  EXPECT_LT(modulus_error(elastic, Eigen::Vector3d(1.05, 1.05, 0.9).asDiagonal()), 1e-6);  // two equal
}

TEST(KirchhoffModulus, EqualsCentralDifferencesOfTheJ2ExponentialMapAtAPlasticState) {
  const auto mat = make_material(plastic());
  std::vector<double> committed(static_cast<size_t>(mat->state_size()), 0.0), trial(committed.size());
  Voigt6 tau;
  mat->update_finite(general_stretch(), committed.data(), trial.data(), tau, nullptr);
  ASSERT_GT(trial[static_cast<size_t>(mat->equivalent_plastic_strain_index())], 0.0);  // the point yields
  EXPECT_LT(modulus_error(plastic(), general_stretch()), 1e-6);
  EXPECT_LT(modulus_error(plastic(), Eigen::Vector3d(1.2, 1.2, 1 / 1.44).asDiagonal()), 1e-6);  // two equal
}

TEST(KirchhoffModulus, PlaneColumnsAreThoseOfTheFullModulus) {
  const auto mat = make_material(plastic());
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F.topLeftCorner<2, 2>() << 1.08, 0.05, -0.03, 0.94;  // plane strain: no z coupling
  FiniteTangent t;
  kirchhoff(*mat, F, &t);
  const Eigen::Matrix<double, 9, 9> full = kirchhoff_modulus(t), plane = kirchhoff_modulus(t, 2);
  for (int m = 0; m < 3; ++m)
    for (int l = 0; l < 3; ++l) {
      const int c = m * 3 + l;
      if (m < 2 && l < 2)
        EXPECT_EQ(plane.col(c), full.col(c)) << c;
      else
        EXPECT_TRUE(plane.col(c).isZero(0.0)) << c;
    }
}

TEST(KirchhoffModulus, LogDividedDifferenceIsAccurateForCloseArguments) {
  EXPECT_NEAR(log_divided_difference(2.0, 0.5), std::log(4.0) / 1.5, 1e-15);
  EXPECT_DOUBLE_EQ(log_divided_difference(0.8, 0.8), 1 / 0.8);
  for (double gap : {1e-3, 1e-5, 1e-9}) {  // 1 / √(ab) (1 − (a − b)² / (24 ab)) to the next order
    const double a = 1.3, b = a * (1 + gap);
    const double expected = 1 / std::sqrt(a * b) * (1 - std::pow(a - b, 2) / (24 * a * b));
    EXPECT_NEAR(log_divided_difference(a, b) / expected, 1.0, 1e-13) << gap;
    EXPECT_NEAR(log_divided_difference(b, a), log_divided_difference(a, b), 1e-15);
  }
}

}  // namespace test_kirchhoff_modulus
