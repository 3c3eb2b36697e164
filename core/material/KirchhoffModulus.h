#pragma once
// The spatial modulus of a finite-strain update in closed form: how the Kirchhoff stress changes when the current
// configuration is moved by a small displacement gradient, dτ / d(∇_x u). The update maps the elastic trial strain
// ε = ½ ln b (b the elastic left Cauchy–Green trial tensor) to τ with an algorithmic modulus dτ/dε; moving the
// configuration by ∇_x u = E changes b by E b + b Eᵀ, and ln's derivative is Daleckii–Krein's: in b's eigenbasis
// the change of ln b is the change of b times the divided differences of ln over b's eigenvalues. Exact for any
// isotropic update of that form (Hencky, and J2's exponential map: Simo 1992, de Souza Neto et al. §14.5).
#include <Eigen/Dense>

#include "material/Material.h"

namespace rollsim {

/// dτ / d(∇_x u) at `t`: column m·3 + l holds the change of τ (a 3 × 3 tensor, column-major) per unit (∇_x u)_ml,
/// for m, l < dim (the other columns zero: a plane-strain element's displacement gradient has no z row or column).
Eigen::Matrix<double, 9, 9> kirchhoff_modulus(const FiniteTangent& t, int dim = 3);

/// (ln a − ln b) / (a − b), and 1 / a when a = b, for a, b > 0 (accurate when they are close).
double log_divided_difference(double a, double b);

}  // namespace rollsim
