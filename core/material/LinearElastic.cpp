#include "material/LinearElastic.h"

#include <cmath>

namespace rollsim {

Eigen::Matrix<double, 6, 6> LinearElastic::tangent3d() const {
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  const double l = lambda(), m = mu();
  D.topLeftCorner<3, 3>().setConstant(l);
  for (int i = 0; i < 3; ++i) {
    D(i, i) = l + 2.0 * m;
    D(3 + i, 3 + i) = m;
  }
  return D;
}

Eigen::Matrix<double, 4, 4> LinearElastic::tangent_plane_strain() const {
  Eigen::Matrix<double, 4, 4> D = Eigen::Matrix<double, 4, 4>::Zero();
  D.topLeftCorner<3, 3>() = tangent3d().topLeftCorner<3, 3>();
  D(3, 3) = mu();
  return D;
}

double von_mises(const double* s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

}  // namespace rollsim
