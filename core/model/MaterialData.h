#pragma once
// What a body is made of, as plain data: the element formulation and the material's parameters as the project
// gives them. The behaviour (stress and tangent from the deformation and the state) lives in material/.
namespace rollsim {

/// Element formulation of a body: full 2×2(×2) Gauss integration or selective B-bar (mean dilatation).
enum class Formulation { Full, BBar };

/// Parameters of an isotropic material [project units]. The nonlinear layer adds a yield stress and a hardening
/// law: a body is plastic when its material has a yield stress.
struct MaterialData {
  double E = 1.0;   // Young's modulus [stress]
  double nu = 0.3;  // Poisson's ratio [-]
};

}  // namespace rollsim
