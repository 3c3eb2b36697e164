#pragma once
// Linear isotropic elasticity (Hooke), Voigt notation with engineering shear strains.
#include <Eigen/Dense>

namespace rollsim {

struct LinearElastic {
  double E = 1.0;   // Young's modulus [stress]
  double nu = 0.3;  // Poisson's ratio [-]

  double lambda() const { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
  double mu() const { return E / (2.0 * (1.0 + nu)); }

  /// 6x6 constitutive matrix, Voigt order xx, yy, zz, xy, yz, zx.
  Eigen::Matrix<double, 6, 6> tangent3d() const;
  /// 4x4 plane-strain matrix, order xx, yy, zz, xy (eps_zz is carried for B-bar; it is 0 with full integration).
  Eigen::Matrix<double, 4, 4> tangent_plane_strain() const;
};

/// Von Mises equivalent stress of a 6-component stress (xx, yy, zz, xy, yz, zx).
double von_mises(const double* s6);

}  // namespace rollsim
