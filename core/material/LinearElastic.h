#pragma once
// Linear isotropic elasticity (Hooke), Voigt notation with engineering shear strains: the first Material.
#include "material/Material.h"

namespace rollsim {

class LinearElastic final : public Material {
 public:
  LinearElastic(double E, double nu) : E_(E), nu_(nu), C_(hooke(lambda(), mu())) {}
  std::string name() const override { return "linear_elastic"; }
  /// σ = C ε, tangent C; no state.
  void update(const Deformation& d, const double* committed, double* trial, Voigt6& stress,
              Tangent6& tangent) const override;

  double lambda() const { return E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_)); }
  double mu() const { return E_ / (2.0 * (1.0 + nu_)); }
  /// 6x6 constitutive matrix, Voigt order xx, yy, zz, xy, yz, zx.
  const Tangent6& tangent3d() const { return C_; }

 private:
  static Tangent6 hooke(double lambda, double mu);
  double E_, nu_;  // Young's modulus [stress], Poisson's ratio [-]
  Tangent6 C_;     // built once: an update is called at every integration point of every assembly
};

}  // namespace rollsim
