// The spectrum shared by a finite-strain point's logarithm, exponential map and modulus: it rebuilds the tensor, its
// eigenvectors are orthonormal, the plane-strain closed form agrees with the general solver (also at a repeated
// in-plane pair) and keeps what it builds exactly plane.
#include <gtest/gtest.h>

#include <cmath>

#include "material/Material.h"
#include "material/Spectrum.h"

namespace test_spectrum {

using namespace rollsim;

namespace {
double rebuild_error(const Eigen::Matrix3d& a) {
  const Spectrum s = spectrum(a);
  const double orthonormal = (s.vectors.transpose() * s.vectors - Eigen::Matrix3d::Identity()).norm();
  return std::max((compose(s, s.values) - a).norm() / a.norm(), orthonormal);
}

Eigen::Matrix3d plane(double xx, double yy, double xy, double zz) {
  Eigen::Matrix3d a;
  a << xx, xy, 0, xy, yy, 0, 0, 0, zz;
  return a;
}
}  // namespace

TEST(Spectrum, RebuildsAGeneralSymmetricTensor) {
  Eigen::Matrix3d a;
  a << 1.3, 0.2, -0.1, 0.2, 0.9, 0.05, -0.1, 0.05, 1.1;
  EXPECT_LT(rebuild_error(a), 1e-14);
}

TEST(Spectrum, PlaneClosedFormRebuildsAndAgreesWithTheGeneralSolver) {
  for (const Eigen::Matrix3d& a : {plane(1.21, 0.83, 0.17, 1.0), plane(0.9, 1.4, -0.3, 0.95), plane(1.0, 1.0, 0.0, 1.0),
                                   plane(1.0 + 1e-9, 1.0, 1e-12, 0.7)}) {
    EXPECT_LT(rebuild_error(a), 1e-15);
    Eigen::Vector3d mine = spectrum(a).values;
    Eigen::Vector3d general = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(a).eigenvalues();
    std::sort(mine.data(), mine.data() + 3);
    EXPECT_LT((mine - general).norm(), 1e-15);
  }
}

TEST(Spectrum, PlaneTensorFunctionsStayExactlyPlane) {
  const Spectrum s = spectrum(plane(1.3, 0.8, 0.21, 0.92));
  const Eigen::Matrix3d log_b = compose(s, s.values.array().log().matrix());
  EXPECT_EQ(log_b(0, 2), 0.0);
  EXPECT_EQ(log_b(1, 2), 0.0);
  EXPECT_EQ(log_b(2, 0), 0.0);
  EXPECT_DOUBLE_EQ(log_b(2, 2), std::log(0.92));
  const Voigt6 e = log_strain(s);  // ½ ln b: the same numbers in Voigt form
  EXPECT_DOUBLE_EQ(e(0), 0.5 * log_b(0, 0));
  EXPECT_DOUBLE_EQ(e(3), log_b(0, 1));
  EXPECT_EQ(e(4), 0.0);
  EXPECT_EQ(e(5), 0.0);
}

}  // namespace test_spectrum
