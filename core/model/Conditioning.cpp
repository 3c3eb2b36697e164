#include "model/Conditioning.h"

#include <cmath>
#include <cstdio>

namespace rollsim {

namespace {
std::string number(double v, int digits = 3) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

void stiffness_ratio(const Model& model, std::vector<std::string>& warnings) {
  const Body *stiff = nullptr, *soft = nullptr;
  for (const Body& b : model.bodies) {
    if (!stiff || b.material.E > stiff->material.E) stiff = &b;
    if (!soft || b.material.E < soft->material.E) soft = &b;
  }
  if (!stiff || soft->material.E <= 0) return;
  const double ratio = stiff->material.E / soft->material.E;
  if (ratio < kStiffnessRatioWarning) return;
  warnings.push_back("the bodies' Young's moduli span a ratio of " + number(ratio) + " (body '" + stiff->name +
                     "' E = " + number(stiff->material.E) + ", body '" + soft->name +
                     "' E = " + number(soft->material.E) + "): double precision keeps about " +
                     number(std::max(0.0, 16 - std::log10(ratio))) +
                     " significant digits of the softer body's forces and reactions — rescale the moduli or hold "
                     "the stiff body by conditions instead");
}

void locking(const Model& model, std::vector<std::string>& warnings) {
  for (const Body& b : model.bodies) {
    const double nu = b.material.nu;
    if (b.formulation != Formulation::Full || nu <= kLockingPoisson) continue;
    warnings.push_back("body '" + b.name + "' is nearly incompressible (ν = " + number(nu, 6) + ", bulk modulus " +
                       number(2 * (1 + nu) / (3 * (1 - 2 * nu))) +
                       " times the shear modulus) under full integration, which locks: its displacements come out "
                       "far too small — use \"formulation\": \"bbar\"");
  }
}
}  // namespace

std::vector<std::string> conditioning_warnings(const Model& model) {
  std::vector<std::string> warnings;
  stiffness_ratio(model, warnings);
  locking(model, warnings);
  return warnings;
}

}  // namespace rollsim
