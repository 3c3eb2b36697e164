#include "model/PrescribedMotion.h"

#include <cmath>

namespace rollsim {

std::array<double, 3> rotation_displacement(const RigidRotation& r, const std::array<double, 3>& X, double lf) {
  const double th = lf * r.angle, c = std::cos(th), s = std::sin(th);
  const std::array<double, 3>& k = r.axis;
  const std::array<double, 3> v{X[0] - r.center[0], X[1] - r.center[1], X[2] - r.center[2]};
  const double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
  const std::array<double, 3> kxv{k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
  std::array<double, 3> u{};
  for (int i = 0; i < 3; ++i) u[i] = (c - 1.0) * (v[i] - k[i] * kv) + s * kxv[i];  // R v − v
  return u;
}

std::optional<double> prescribed_value(const DisplacementBC& bc, const std::array<double, 3>& X, int comp, double lf) {
  if (!bc.rotation) {
    if (!bc.value[comp]) return std::nullopt;
    return lf == 1.0 ? *bc.value[comp] : lf * *bc.value[comp];
  }
  return rotation_displacement(*bc.rotation, X, lf)[comp] + lf * bc.value[comp].value_or(0.0);
}

}  // namespace rollsim
