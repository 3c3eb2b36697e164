#pragma once
// The eigen-decomposition of a symmetric 3 × 3 tensor, computed once per integration point and shared by what needs
// it there: the logarithmic strain ½ ln b, the exponential map back to b_e, and the spatial modulus (Daleckii–Krein
// over b's eigenvalues). In plane strain (no xz, yz coupling) it is a closed-form 2 × 2 rotation and the zz value.
#include <Eigen/Dense>

namespace rollsim {

struct Spectrum {
  Eigen::Vector3d values;   // eigenvalues (no particular order)
  Eigen::Matrix3d vectors;  // orthonormal eigenvectors, column k for values(k)
};

/// The spectrum of a symmetric tensor `a`. When a(0,2) and a(1,2) are exactly zero (plane strain) the in-plane pair
/// comes from one Jacobi rotation and e_z is an exact eigenvector, so quantities built from it stay plane.
Spectrum spectrum(const Eigen::Matrix3d& a);

/// Q diag(f) Qᵀ: the isotropic tensor function with principal values f on the spectrum's eigenvectors.
Eigen::Matrix3d compose(const Spectrum& s, const Eigen::Vector3d& f);

}  // namespace rollsim
