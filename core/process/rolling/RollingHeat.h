#pragma once
// A rolling pass with heat (process.heat_transfer): the slab and the roll conduct, the roll–slab contact passes heat
// through its conductance, the slab's free surfaces lose heat to the air (convection and radiation) and the roll's
// surface to its cooling; plastic and friction work heat them (analysis/HeatConduction). Defaults for hot carbon
// steel on a steel roll. Units with mm, N and s: W/(m·K), MPa/K, kW/(m²·K), °C.
#include <vector>

#include "base/Schema.h"

namespace rollsim {

/// The schema of process.heat_transfer.
const ObjectSchema& rolling_heat_schema();

/// The slab's heat capacity ρc [MPa/K] when the project gives none: hot carbon steel, about 7.6e3 kg/m³ × 650 J/(kg K).
constexpr double kHotSteelHeatCapacity = 4.9;

/// process.heat_transfer in the process's terms: it needs the roll's speed (the time heat flows over).
void check_rolling_heat(const json& process, std::vector<Issue>& issues);

/// The pass's heat into the expanded project `out` (its materials 'slab' and 'roll', its contact 'roll-slab' and a
/// `heat` section cooling the slab's free surfaces and the roll's), from the validated section `process`.
void expand_rolling_heat(const json& process, int dim, json& out);

}  // namespace rollsim
