#pragma once
// The registered flow stress laws (material/FlowStress), one file each: Hensel–Spittel's (the Freiberg form QForm
// and FORGE take their coefficients in), Shida's for carbon steels, Johnson–Cook's; and the rate- and temperature-
// independent hardening a material gives with its own fields.
#include "material/FlowStress.h"

namespace rollsim {

const FlowStressLaw& hensel_spittel_law();
const FlowStressLaw& shida_law();
const FlowStressLaw& johnson_cook_law();
/// σ_0 + H ε + (σ_∞ − σ_0)(1 − exp(−δ ε)) from the material's yield_stress, hardening_modulus and saturation_*.
std::unique_ptr<FlowStress> make_saturation_hardening(const MaterialData& data);

/// The fields every law has: the strain and rate offsets, with a law's defaults.
Field strain_offset_field(double d);
Field rate_offset_field(double d);

}  // namespace rollsim
