#pragma once
// Finite-strain kernel of the Q4 (plane strain) and H8 elements: total displacements on the reference mesh, the
// spatial (updated-Lagrangian) form f_a = ∫_V0 τ ∇_x N_a dV0 with τ the Kirchhoff stress of the material's
// finite-strain update (Material::update_finite), and — for the `bbar` formulation — F-bar (de Souza Neto, Perić,
// Dunavant & Owen 1996): F̄ = (J_0 / J)^{1/d} F with J_0 at the element centre, which keeps isochoric plastic flow
// from locking. The tangent is the exact linearisation (geometric stiffness and the F-bar term included) with the
// material's spatial modulus dτ/d(∇_x u) in closed form (material/KirchhoffModulus); it is unsymmetric with F-bar,
// and the assembler keeps its symmetric part (CHOLMOD factors the bodies).
#include "fem/SolidElement.h"

namespace rollsim {

/// What a Newton assembly does with its finite-strain points' material updates: nothing; keeps them (a residual that
/// a tangent at the same iterate may follow); or takes them from the kept ones wherever an element's displacement is
/// the one they were kept for — the caller vouches that the state has not changed since they were kept.
enum class PointMemo { off, keep, reuse };

template <int D>
struct FiniteStrainElement {
  using El = SolidElement<D>;
  using Stress6 = typename El::Stress6;

  /// What the material's update gave at an element's points for one displacement: kept by a force-only evaluation,
  /// so that the tangent asked for next at the same displacement and state (a selective Newton iteration takes every
  /// group's residual, then the tangents of those it refactors) skips the update and writes no trial state.
  struct PointUpdates {
    typename El::Dofs ue;                     // the displacement they are for
    std::array<Voigt6, El::NGP> tau;          // the Kirchhoff stress of F̄
    std::array<FiniteTangent, El::NGP> with;  // what the modulus is built from
    bool valid = false;
  };

  /// f_e (and, when Ke is not null, the full tangent) at element displacements ue; stresses (if not null): the
  /// Cauchy stress σ = τ / J at every Gauss point. State as in SolidElement::tangent_and_force. False if inverted.
  static bool tangent_and_force(const typename El::Coords& X, const Material& mat, Formulation f,
                                const typename El::Dofs& ue, const double* committed, double* trial,
                                typename El::Stiffness* Ke, typename El::Dofs& fe,
                                std::array<Stress6, El::NGP>* stresses = nullptr);
  /// The same from the reference geometry of the element (its gradients computed once: ElementGeometryCache).
  /// With `memo`: its points kept (PointMemo::keep) or taken from it (PointMemo::reuse, where it holds ue; the trial
  /// state is then the one written when it was kept).
  static bool tangent_and_force(const typename El::Geometry& reference, const Material& mat, Formulation f,
                                const typename El::Dofs& ue, const double* committed, double* trial,
                                typename El::Stiffness* Ke, typename El::Dofs& fe,
                                std::array<Stress6, El::NGP>* stresses = nullptr, PointUpdates* memo = nullptr,
                                PointMemo mode = PointMemo::keep);
};

extern template struct FiniteStrainElement<2>;
extern template struct FiniteStrainElement<3>;

}  // namespace rollsim
