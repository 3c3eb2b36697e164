#pragma once
// J2 (von Mises) plasticity with isotropic hardening, small strain: radial return and its consistent (algorithmic)
// tangent (Simo & Hughes 1998, box 3.2; de Souza Neto, Perić & Owen 2008, box 7.4). The return is the one the
// finite-strain layer applies to logarithmic elastic strains (Simo 1992's exponential map), so this class is its
// kernel. State per integration point: plastic strain (6, engineering shears) and equivalent plastic strain α.
#include "material/Material.h"

namespace rollsim {

class J2Plasticity final : public Material {
 public:
  explicit J2Plasticity(const MaterialData& data);
  std::string name() const override { return "j2_plasticity"; }
  int state_size() const override { return kStateSize; }
  int equivalent_plastic_strain_index() const override { return kAlpha; }
  void update(const Deformation& d, const double* committed, double* trial, Voigt6& stress,
              Tangent6& tangent) const override;
  /// Multiplicative plasticity (Simo 1992): b_e trial = F C_p⁻¹ Fᵀ, the return above on ε_e = ½ ln b_e (Hencky
  /// elasticity, τ Kirchhoff), then C_p⁻¹ = F⁻¹ exp(2 ε_e) F⁻ᵀ. State: C_p⁻¹ − I (xx, yy, zz, xy, yz, zx) in the
  /// plastic-strain slots, α.
  void update_finite(const Eigen::Matrix3d& F, const double* committed, double* trial, Voigt6& tau,
                     FiniteTangent* tangent) const override;

  /// σ_y(α) and its slope dσ_y/dα [stress].
  double yield_stress(double alpha) const;
  double hardening_slope(double alpha) const;

  static constexpr int kStateSize = 7;  // ε_p (xx, yy, zz, γxy, γyz, γzx), α
  static constexpr int kAlpha = 6;

 private:
  MaterialData data_;
  double G_, K_;
  Tangent6 elastic_;
};

}  // namespace rollsim
