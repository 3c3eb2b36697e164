#pragma once
// J2 (von Mises) plasticity with isotropic hardening, small strain: radial return and its consistent (algorithmic)
// tangent (Simo & Hughes 1998, box 3.2; de Souza Neto, Perić & Owen 2008, box 7.4). The return is the one the
// finite-strain layer applies to logarithmic elastic strains (Simo 1992's exponential map), so this class is its
// kernel. State per integration point: plastic strain (6, engineering shears) and equivalent plastic strain α. The
// yield stress is a flow stress law σ_f(α, α̇, T) (material/FlowStress): with a rate-dependent one, α̇ = Δα/Δt over
// the increment's time Δt, and the return's scalar equation and consistent tangent take dσ_f/dΔα = ∂σ_f/∂α +
// ∂σ_f/∂α̇ / Δt. With a volumetric heat capacity ρc, plastic work heats each point adiabatically (no conduction yet):
// ΔT = β ∫ τ_y dα / ρc over the step (trapezoid) after the return, staggered — the increment's flow stress is taken at
// its starting temperature, so the tangent has no temperature term.
#include <memory>

#include "material/FlowStress.h"
#include "material/Material.h"

namespace rollsim {

class J2Plasticity final : public Material {
 public:
  /// `dt`: the increment's time [s]. With a rate-dependent law and dt = 0 no time passes: the state is frozen and
  /// the response elastic from it (what recovering the stresses of a converged state asks).
  explicit J2Plasticity(const MaterialData& data, double dt = 0);
  std::string name() const override { return "j2_plasticity"; }
  int state_size() const override { return kStateSize; }
  int equivalent_plastic_strain_index() const override { return kAlpha; }
  int temperature_rise_index() const override { return kHeat; }
  void update(const Deformation& d, const double* committed, double* trial, Voigt6& stress,
              Tangent6& tangent) const override;
  /// Multiplicative plasticity (Simo 1992): b_e trial = F C_p⁻¹ Fᵀ, the return above on ε_e = ½ ln b_e (Hencky
  /// elasticity, τ Kirchhoff), then C_p⁻¹ = F⁻¹ exp(2 ε_e) F⁻ᵀ. State: C_p⁻¹ − I (xx, yy, zz, xy, yz, zx) in the
  /// plastic-strain slots, α.
  void update_finite(const Eigen::Matrix3d& F, const double* committed, double* trial, Voigt6& tau,
                     FiniteTangent* tangent) const override;
  /// C_p⁻¹ becomes b_e = F C_p⁻¹ Fᵀ (with F = I on the new reference, b_e trial = C_p⁻¹; its volume, det b_e = J_e²,
  /// becomes the plastic volume 1 / J_p² that update_finite scales the stress by); α and ΔT stay.
  void rebase_state(const Eigen::Matrix3d& F, double* state) const override;
  /// 1 / √det C_p⁻¹, or 1 where that is within kUnitVolume of it (plastic flow alone: round-off).
  double plastic_volume(const double* state) const override;

  /// σ_y at equivalent plastic strain α reached by Δα in this increment, the point `rise` above the material's
  /// temperature, and its slope dσ_y/dΔα [stress].
  FlowStressPoint yield_stress(double alpha, double increment = 0, double rise = 0) const;

  static constexpr int kStateSize = 8;  // ε_p (xx, yy, zz, γxy, γyz, γzx), α, the temperature rise ΔT [K]
  static constexpr int kAlpha = 6;
  static constexpr int kHeat = 7;
  /// |J_p − 1| below which a state's plastic volume is round-off of isochoric flow, not a rebased reference's
  static constexpr double kUnitVolume = 1e-9;

 private:
  /// Δα of the return from the trial von Mises stress q: q − 3G Δα = σ_y(α_n + Δα), Newton safeguarded by bisection
  /// (a rate-dependent σ_y rises steeply from zero rate).
  double plastic_increment(double q, double alpha_n, double rise) const;

  std::unique_ptr<FlowStress> flow_;
  double dt_, temperature_;
  double heating_;  // β / ρc [K / stress]: the temperature rise per unit plastic work (0: none)
  bool frozen_;     // rate-dependent without time: no return
  double G_, K_;
  Tangent6 elastic_;
};

}  // namespace rollsim
