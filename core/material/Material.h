#pragma once
// One interface for a material's behaviour at an integration point: stress and consistent tangent from the
// deformation and the state committed at the end of the last converged increment, with the trial state written
// beside it (the driver commits it only when the increment converges). Made by name from the model's MaterialData.
#include <Eigen/Dense>
#include <memory>
#include <string>

#include "material/Spectrum.h"
#include "model/MaterialData.h"

namespace rollsim {

using Voigt6 = Eigen::Matrix<double, 6, 1>;    // xx, yy, zz, xy, yz, zx (engineering shear strains)
using Tangent6 = Eigen::Matrix<double, 6, 6>;  // dσ/dε in the same order

/// The deformation at an integration point: the small strain (small-strain kinematics).
struct Deformation {
  Voigt6 strain = Voigt6::Zero();
};

/// What a finite-strain update's spatial tangent is made of (material/KirchhoffModulus): the algorithmic modulus
/// dτ/dε of its return (ε = ½ ln b, engineering shears) and the spectrum of the elastic trial left Cauchy–Green
/// tensor b (the one the update decomposed: the modulus needs b only through its eigenpairs).
struct FiniteTangent {
  Tangent6 modulus;
  Spectrum b;
};

class Material {
 public:
  virtual ~Material() = default;
  virtual std::string name() const = 0;
  /// State variables per integration point (0: no state, as for elastic materials).
  virtual int state_size() const { return 0; }
  /// Where the equivalent plastic strain sits in the state (-1: the material has none).
  virtual int equivalent_plastic_strain_index() const { return -1; }
  /// Where the temperature rise from plastic work sits in the state [K] (-1: the material has none).
  virtual int temperature_rise_index() const { return -1; }
  /// σ and the consistent tangent at one integration point from `d` and the committed state (`state_size()`
  /// values); writes the trial state into `trial` (both may be null when state_size() is 0).
  virtual void update(const Deformation& d, const double* committed, double* trial, Voigt6& stress,
                      Tangent6& tangent) const = 0;
  /// Finite strain (isotropic, logarithmic elastic strains — Simo 1992): the Kirchhoff stress τ (Voigt, tensor
  /// components) from the deformation gradient F and the committed state, the trial state written (both null
  /// without state), and what its tangent needs when `tangent` is not null. This default, for materials without
  /// state, is Hencky's hyperelastic law: τ = update(ln V), V² = F Fᵀ. Plastic materials override it with the
  /// exponential map around their return.
  virtual void update_finite(const Eigen::Matrix3d& F, const double* committed, double* trial, Voigt6& tau,
                             FiniteTangent* tangent) const;
  /// Finite strain: a committed state as it reads on a reference configuration that is the current one, F the
  /// deformation gradient there from the old reference (a remesh's new mesh starts at the current positions, F = I):
  /// update_finite(I, rebased) gives the Cauchy stress update_finite(F, state) gave (τ per the new reference's volume:
  /// the old τ / det F). Default: no state to change.
  virtual void rebase_state(const Eigen::Matrix3d& /*F*/, double* /*state*/) const {}
  /// The plastic volume J_p a finite-strain state holds (≠ 1 on a rebased reference, which is under elastic strain):
  /// the mass of a unit of reference volume is J_p times the original density's. Default: 1.
  virtual double plastic_volume(const double* /*state*/) const { return 1.0; }
  /// The tangent at zero deformation and the initial state: the stiffness of a linear analysis.
  Tangent6 initial_tangent() const;
};

/// The behaviour for `data`: J2Plasticity when it is plastic (a yield stress or a flow stress law), else
/// LinearElastic; `dt` is the time of the increment it is updated over [s] (0: none, as for a stress recovery).
std::unique_ptr<Material> make_material(const MaterialData& data, double dt = 0);

/// ½ ln(b) of a symmetric positive definite b given by its spectrum, as a Voigt strain (engineering shears).
Voigt6 log_strain(const Spectrum& b);
/// The Voigt strain (engineering shears) of a symmetric tensor.
Voigt6 voigt_strain(const Eigen::Matrix3d& E);
/// The symmetric tensor of a Voigt strain (engineering shears halved).
Eigen::Matrix3d strain_tensor(const Voigt6& e);
/// The symmetric tensor of a Voigt stress (tensor shears).
Eigen::Matrix3d stress_tensor(const Voigt6& s);

/// Von Mises equivalent stress of a 6-component stress (xx, yy, zz, xy, yz, zx).
double von_mises(const double* s6);

}  // namespace rollsim
