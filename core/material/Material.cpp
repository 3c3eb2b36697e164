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

std::unique_ptr<Material> make_material(const MaterialData& data) {
  if (data.plastic()) return std::make_unique<J2Plasticity>(data);
  return std::make_unique<LinearElastic>(data.E, data.nu);
}

double von_mises(const double* s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

}  // namespace rollsim
