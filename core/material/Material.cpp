#include "material/Material.h"

#include <cmath>
#include <vector>

#include "material/J2Plasticity.h"
#include "material/LinearElastic.h"

namespace rollsim {

Tangent6 Material::initial_tangent() const {
  Voigt6 stress;
  Tangent6 tangent;
  if (state_size() == 0) {  // no state to start from (called once per element: no allocation)
    update(Deformation{}, nullptr, nullptr, stress, tangent);
    return tangent;
  }
  std::vector<double> committed(static_cast<size_t>(state_size()), 0.0), trial(committed.size());
  update(Deformation{}, committed.data(), trial.data(), stress, tangent);
  return tangent;
}

Voigt6 log_strain(const Spectrum& b) { return voigt_strain(compose(b, 0.5 * b.values.array().log())); }

Voigt6 voigt_strain(const Eigen::Matrix3d& E) {
  Voigt6 e;
  e << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(1, 2), 2 * E(2, 0);
  return e;
}

Eigen::Matrix3d strain_tensor(const Voigt6& e) {
  Eigen::Matrix3d E;
  E << e(0), e(3) / 2, e(5) / 2, e(3) / 2, e(1), e(4) / 2, e(5) / 2, e(4) / 2, e(2);
  return E;
}

Eigen::Matrix3d stress_tensor(const Voigt6& s) {
  Eigen::Matrix3d t;
  t << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
  return t;
}

void Material::update_finite(const Eigen::Matrix3d& F, const double* committed, double* trial, Voigt6& tau,
                             FiniteTangent* tangent) const {
  Deformation d;
  const Spectrum b = spectrum(F * F.transpose());
  d.strain = log_strain(b);
  Tangent6 modulus;
  update(d, committed, trial, tau, modulus);
  if (tangent) *tangent = {modulus, b};
}

std::unique_ptr<Material> make_material(const MaterialData& data, double dt) {
  if (data.plastic()) return std::make_unique<J2Plasticity>(data, dt);
  return std::make_unique<LinearElastic>(data.E, data.nu);
}

double von_mises(const double* s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

}  // namespace rollsim
