#include "material/J2Plasticity.h"

#include <cmath>
#include <stdexcept>

#include "material/LinearElastic.h"

namespace rollsim {

namespace {
/// Deviatoric projector from engineering strains to deviatoric strain tensor components (shear rows: γ/2).
Tangent6 deviatoric_projector() {
  Tangent6 P = Tangent6::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) P(i, j) = (i == j ? 1.0 : 0.0) - 1.0 / 3.0;
    P(3 + i, 3 + i) = 0.5;
  }
  return P;
}

/// s : s of a symmetric tensor in Voigt stress order (tensor shear components).
double contract(const Voigt6& s) { return s.head<3>().squaredNorm() + 2.0 * s.tail<3>().squaredNorm(); }
}  // namespace

J2Plasticity::J2Plasticity(const MaterialData& data) : data_(data) {
  const LinearElastic e(data.E, data.nu);
  G_ = e.mu();
  K_ = e.lambda() + 2.0 * G_ / 3.0;
  elastic_ = e.tangent3d();
}

double J2Plasticity::yield_stress(double a) const {
  double s = data_.yield_stress + data_.hardening_modulus * a;
  if (data_.saturation_stress > data_.yield_stress)
    s += (data_.saturation_stress - data_.yield_stress) * (1.0 - std::exp(-data_.saturation_exponent * a));
  return s;
}

double J2Plasticity::hardening_slope(double a) const {
  double h = data_.hardening_modulus;
  if (data_.saturation_stress > data_.yield_stress)
    h += (data_.saturation_stress - data_.yield_stress) * data_.saturation_exponent *
         std::exp(-data_.saturation_exponent * a);
  return h;
}

void J2Plasticity::update(const Deformation& d, const double* committed, double* trial, Voigt6& stress,
                          Tangent6& tangent) const {
  const Eigen::Map<const Voigt6> ep_n(committed);
  const double alpha_n = committed[kAlpha];
  stress = elastic_ * (d.strain - ep_n);  // elastic trial
  tangent = elastic_;
  Eigen::Map<Voigt6> ep(trial);
  ep = ep_n;
  trial[kAlpha] = alpha_n;
  Voigt6 s = stress;
  const double p = stress.head<3>().sum() / 3.0;
  s.head<3>().array() -= p;
  const double q = std::sqrt(1.5 * contract(s));  // von Mises of the trial stress
  if (q - yield_stress(alpha_n) <= 1e-12 * yield_stress(alpha_n)) return;
  // Δγ from q − 3G Δγ − σ_y(α_n + Δγ) = 0 (Newton; one step for linear hardening)
  double dg = 0.0;
  for (int it = 0; it < 50; ++it) {
    const double r = q - 3.0 * G_ * dg - yield_stress(alpha_n + dg);
    const double slope = 3.0 * G_ + hardening_slope(alpha_n + dg);
    dg += r / slope;
    if (std::abs(r) <= 1e-13 * q) break;
  }
  if (!(dg > 0.0) || !std::isfinite(dg)) throw std::runtime_error("J2 return mapping failed to converge");
  const Voigt6 n = s / std::sqrt(contract(s));  // unit normal, tensor components
  const double scale = 1.0 - 3.0 * G_ * dg / q;
  stress.head<3>() = s.head<3>() * scale + Voigt6::Constant(p).head<3>();
  stress.tail<3>() = s.tail<3>() * scale;
  // plastic strain increment Δγ N, N = (3/2) s / q = sqrt(3/2) n; engineering shears twice the tensor ones
  Voigt6 dep = std::sqrt(1.5) * dg * n;
  dep.tail<3>() *= 2.0;
  ep = ep_n + dep;
  trial[kAlpha] = alpha_n + dg;
  const double H = hardening_slope(alpha_n + dg);
  tangent = elastic_ - (6.0 * G_ * G_ * dg / q) * deviatoric_projector() +
            6.0 * G_ * G_ * (dg / q - 1.0 / (3.0 * G_ + H)) * (n * n.transpose());
}

void J2Plasticity::update_finite(const Eigen::Matrix3d& F, const double* committed, double* trial, Voigt6& tau,
                                 FiniteTangent* tangent) const {
  Eigen::Matrix3d Cp_inv;
  const double* c = committed;
  Cp_inv << 1 + c[0], c[3], c[5], c[3], 1 + c[1], c[4], c[5], c[4], 1 + c[2];
  Deformation d;
  const Spectrum b = spectrum(F * Cp_inv * F.transpose());  // elastic trial left Cauchy–Green tensor
  d.strain = log_strain(b);
  double log_committed[kStateSize] = {0, 0, 0, 0, 0, 0, committed[kAlpha]}, log_trial[kStateSize];
  Tangent6 modulus;
  update(d, log_committed, log_trial, tau, modulus);
  if (tangent) *tangent = {modulus, b};
  std::copy(committed, committed + kStateSize, trial);
  trial[kAlpha] = log_trial[kAlpha];
  if (log_trial[kAlpha] == committed[kAlpha]) return;  // elastic: C_p unchanged
  // ε_e = ε_e trial − Δε_p, coaxial with b (Δε_p ∝ the trial deviator), so b_e = exp(2 ε_e) = Q diag(λ e^(−2 Δε_p,k))
  // Qᵀ with Δε_p,k its principal values on b's eigenvectors
  const Eigen::Matrix3d dep = strain_tensor(Eigen::Map<const Voigt6>(log_trial));
  const Eigen::Vector3d dep_principal = (b.vectors.transpose() * dep * b.vectors).diagonal();
  const Eigen::Matrix3d be = compose(b, b.values.cwiseProduct((-2 * dep_principal).array().exp().matrix()));
  const Eigen::Matrix3d Finv = F.inverse();
  const Eigen::Matrix3d C = Finv * be * Finv.transpose();
  trial[0] = C(0, 0) - 1;
  trial[1] = C(1, 1) - 1;
  trial[2] = C(2, 2) - 1;
  trial[3] = 0.5 * (C(0, 1) + C(1, 0));
  trial[4] = 0.5 * (C(1, 2) + C(2, 1));
  trial[5] = 0.5 * (C(2, 0) + C(0, 2));
}

}  // namespace rollsim
