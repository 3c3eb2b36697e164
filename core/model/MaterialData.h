#pragma once
// What a body is made of, as plain data: the element formulation and the material's parameters as the project
// gives them. The behaviour (stress and tangent from the deformation and the state) lives in material/.
#include <map>
#include <string>

#include "model/ThermalTable.h"

namespace rollsim {

/// Element formulation of a body: full 2×2(×2) Gauss integration or selective B-bar (mean dilatation; with finite
/// kinematics its counterpart F-bar).
enum class Formulation { Full, BBar };

/// Kinematics of a body: small strain, or finite strain (large displacements and rotations, logarithmic strains).
enum class Kinematics { Small, Finite };

/// A flow stress law by name (material/FlowStressLaws: hensel_spittel, shida, johnson_cook) and its coefficients
/// by their schema names, as the project gives them.
struct FlowStressData {
  std::string law;  // empty: the material's own hardening (yield_stress, hardening_modulus, saturation_*)
  std::map<std::string, double> coefficients;
};

/// Parameters of an isotropic material [project units]. A body is plastic (J2, isotropic hardening) when its
/// material has a yield stress, σ_y(α) = σ_0 + H α + (σ_∞ − σ_0)(1 − exp(−δ α)), α the equivalent plastic strain
/// (linear hardening when σ_∞ = σ_0, the default), or a flow stress law σ_f(α, α̇, T).
struct MaterialData {
  double E = 1.0;                    // Young's modulus [stress]
  double nu = 0.3;                   // Poisson's ratio [-]
  double yield_stress = 0.0;         // σ_0 [stress]; 0: elastic
  double hardening_modulus = 0.0;    // H [stress]
  double saturation_stress = 0.0;    // σ_∞ [stress]; ≤ σ_0: no saturation term
  double saturation_exponent = 0.0;  // δ [-]
  FlowStressData flow_stress;        // a law of strain, strain rate and temperature instead of the hardening above
  double temperature = 20.0;  // the body's initial temperature [°C], uniform (what a flow stress law is taken at)
  // volumetric ρc [stress / K]: plastic work heats it (0: never). With a thermal_table's ρc(T), the table's value at
  // `temperature`: conduction reads the table, and this stays the factor of plastic work's adiabatic rise
  double heat_capacity = 0.0;
  double taylor_quinney = 0.9;  // β: the share of plastic work turned into heat [-]
  // thermal conductivity k [W/(m K) = N/(s K) with mm, N and s]: with a heat capacity, the body conducts heat
  // (nodal temperatures, analysis/HeatConduction); 0: each point keeps its own heat (adiabatic)
  // (with a thermal_table's k(T): the table's value at `temperature`, and conduction reads the table)
  double conductivity = 0.0;
  ThermalTable thermal_table;  // k(T) and ρc(T) of heat conduction (empty: the constants above)

  bool plastic() const { return yield_stress > 0.0 || !flow_stress.law.empty(); }
  /// Whether its temperature matters: a flow stress law reads it, or plastic work raises it.
  bool thermal() const { return plastic() && (!flow_stress.law.empty() || heat_capacity > 0.0); }
  /// Whether bodies of it carry a nodal temperature field: heat conducts through them.
  bool conducts() const { return conductivity > 0.0 && heat_capacity > 0.0; }
};

}  // namespace rollsim
