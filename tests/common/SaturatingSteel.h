#pragma once
// The J2 material of the tangent tests: steel-like constants (MPa) with linear and saturation hardening, so that
// both hardening terms enter every consistent tangent they check.
#include "model/MaterialData.h"

namespace rollsim::testing {

inline MaterialData saturating_steel() {
  MaterialData m;
  m.E = 200e3;
  m.nu = 0.3;
  m.yield_stress = 250;
  m.hardening_modulus = 2000;
  m.saturation_stress = 400;
  m.saturation_exponent = 10;
  return m;
}

}  // namespace rollsim::testing
