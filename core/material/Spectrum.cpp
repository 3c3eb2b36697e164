#include "material/Spectrum.h"

#include <cmath>

namespace rollsim {

namespace {
/// The in-plane pair of a symmetric tensor with no out-of-plane coupling: eigenvalues m ± r of the xy block
/// (r = √(h² + d²), h = ½ (a_xx − a_yy), d = a_xy), the first's eigenvector (h + r, d) or (d, r − h) normalised,
/// whichever adds two non-negative numbers (no cancellation, no trigonometry); e_z with a_zz.
Spectrum plane_spectrum(const Eigen::Matrix3d& a) {
  const double m = 0.5 * (a(0, 0) + a(1, 1)), h = 0.5 * (a(0, 0) - a(1, 1)), d = a(0, 1);
  const double r = std::sqrt(h * h + d * d);
  double c = 1, s = 0;
  if (r > 0) {
    const double x = h >= 0 ? h + r : d, y = h >= 0 ? d : r - h;
    const double n = std::sqrt(x * x + y * y);
    c = x / n;
    s = y / n;
  }
  Spectrum out;
  out.values << m + r, m - r, a(2, 2);
  out.vectors << c, -s, 0, s, c, 0, 0, 0, 1;
  return out;
}
}  // namespace

Spectrum spectrum(const Eigen::Matrix3d& a) {
  if (a(0, 2) == 0.0 && a(1, 2) == 0.0 && a(2, 0) == 0.0 && a(2, 1) == 0.0) return plane_spectrum(a);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(a);
  return {eig.eigenvalues(), eig.eigenvectors()};
}

Eigen::Matrix3d compose(const Spectrum& s, const Eigen::Vector3d& f) {
  return s.vectors * f.asDiagonal() * s.vectors.transpose();
}

}  // namespace rollsim
