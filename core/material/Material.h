#pragma once
// One interface for a material's behaviour at an integration point: stress and consistent tangent from the
// deformation and the state committed at the end of the last converged increment, with the trial state written
// beside it (the driver commits it only when the increment converges). Made by name from the model's MaterialData.
#include <Eigen/Dense>
#include <memory>
#include <string>

#include "model/MaterialData.h"

namespace rollsim {

using Voigt6 = Eigen::Matrix<double, 6, 1>;    // xx, yy, zz, xy, yz, zx (engineering shear strains)
using Tangent6 = Eigen::Matrix<double, 6, 6>;  // dσ/dε in the same order

/// The deformation at an integration point. Small strain today; the finite-strain layer adds the deformation
/// gradient F.
struct Deformation {
  Voigt6 strain = Voigt6::Zero();
};

class Material {
 public:
  virtual ~Material() = default;
  virtual std::string name() const = 0;
  /// State variables per integration point (0: no state, as for elastic materials).
  virtual int state_size() const { return 0; }
  /// Where the equivalent plastic strain sits in the state (-1: the material has none).
  virtual int equivalent_plastic_strain_index() const { return -1; }
  /// σ and the consistent tangent at one integration point from `d` and the committed state (`state_size()`
  /// values); writes the trial state into `trial` (both may be null when state_size() is 0).
  virtual void update(const Deformation& d, const double* committed, double* trial, Voigt6& stress,
                      Tangent6& tangent) const = 0;
  /// The tangent at zero deformation and the initial state: the stiffness of a linear analysis.
  Tangent6 initial_tangent() const;
};

/// The behaviour for `data`: J2Plasticity when it has a yield stress, else LinearElastic.
std::unique_ptr<Material> make_material(const MaterialData& data);

/// Von Mises equivalent stress of a 6-component stress (xx, yy, zz, xy, yz, zx).
double von_mises(const double* s6);

}  // namespace rollsim
