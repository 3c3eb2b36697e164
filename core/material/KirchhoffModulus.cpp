#include "material/KirchhoffModulus.h"

#include <cmath>

namespace rollsim {

double log_divided_difference(double a, double b) {
  const double x = (a - b) / (a + b);  // ln(a / b) = 2 atanh(x), a − b = x (a + b)
  if (std::abs(x) < 1e-4) return 2.0 / (a + b) * (1.0 + x * x / 3.0);
  return 2.0 * std::atanh(x) / (x * (a + b));
}

Eigen::Matrix<double, 9, 9> kirchhoff_modulus(const FiniteTangent& t, int dim) {
  const Eigen::Vector3d& lambda = t.b.values;
  const Eigen::Matrix3d& Q = t.b.vectors;
  Eigen::Matrix3d G;  // divided differences of ln over the eigenvalues: symmetric, 1 / λ on the diagonal
  for (int a = 0; a < 3; ++a) {
    G(a, a) = log_divided_difference(lambda(a), lambda(a));
    for (int c = a + 1; c < 3; ++c) G(a, c) = G(c, a) = log_divided_difference(lambda(a), lambda(c));
  }
  Eigen::Matrix<double, 9, 9> A = Eigen::Matrix<double, 9, 9>::Zero();
  for (int m = 0; m < dim; ++m)
    for (int l = 0; l < dim; ++l) {
      // Qᵀ (E b + b Eᵀ) Q for E = e_m e_lᵀ: Y + Yᵀ with Y = q_m q_lᵀ Λ, q_m the m-th row of Q
      const Eigen::Matrix3d Y = Q.row(m).transpose() * Q.row(l) * lambda.asDiagonal();
      const Eigen::Matrix3d dE = 0.5 * Q * G.cwiseProduct(Y + Y.transpose()) * Q.transpose();  // d(½ ln b)
      const Eigen::Matrix3d dtau = stress_tensor(t.modulus * voigt_strain(dE));
      A.col(m * 3 + l) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(dtau.data());
    }
  return A;
}

}  // namespace rollsim
