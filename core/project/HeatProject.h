#pragma once
// The project's heat transfer: the `heat` section (the air around the bodies and which surfaces it cools), the
// materials' conductivity and the contacts' conductance, checked at the user's paths and read into the model's
// HeatExchange. Units with mm, N and s: conductivity W/(m·K) = N/(s·K), heat capacity MPa/K = J/(cm³·K), convection
// and conductance kW/(m²·K) = N/(mm·s·K); radiation's Stefan–Boltzmann constant assumes mm, N and s.
#include <vector>

#include "base/Schema.h"
#include "model/Model.h"

namespace rollsim {

/// The `heat` section's schema.
const ObjectSchema& heat_schema();

/// The heat fields of an expanded project: conductivity with a heat capacity, the time conduction needs
/// (analysis.duration), conductances between conducting bodies, cooled surfaces of conducting bodies.
void check_heat(const json& expanded_project, std::vector<Issue>& issues);

/// The `heat` section into model.heat (its bodies and surfaces found by name; the model's bodies built).
void add_heat(Model& model, const json& expanded_project);

}  // namespace rollsim
