#pragma once
// What a body is made of, as plain data: the element formulation and the material's parameters as the project
// gives them. The behaviour (stress and tangent from the deformation and the state) lives in material/.
namespace rollsim {

/// Element formulation of a body: full 2×2(×2) Gauss integration or selective B-bar (mean dilatation; with finite
/// kinematics its counterpart F-bar).
enum class Formulation { Full, BBar };

/// Kinematics of a body: small strain, or finite strain (large displacements and rotations, logarithmic strains).
enum class Kinematics { Small, Finite };

/// Parameters of an isotropic material [project units]. A body is plastic (J2, isotropic hardening) when its
/// material has a yield stress: σ_y(α) = σ_0 + H α + (σ_∞ − σ_0)(1 − exp(−δ α)), α the equivalent plastic strain
/// (linear hardening when σ_∞ = σ_0, the default).
struct MaterialData {
  double E = 1.0;                    // Young's modulus [stress]
  double nu = 0.3;                   // Poisson's ratio [-]
  double yield_stress = 0.0;         // σ_0 [stress]; 0: elastic
  double hardening_modulus = 0.0;    // H [stress]
  double saturation_stress = 0.0;    // σ_∞ [stress]; ≤ σ_0: no saturation term
  double saturation_exponent = 0.0;  // δ [-]

  bool plastic() const { return yield_stress > 0.0; }
};

}  // namespace rollsim
