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

/// The finite-strain state's first six slots as the tensor they hold, C_p⁻¹ (stored as C_p⁻¹ − I).
Eigen::Matrix3d cp_inverse(const double* c) {
  Eigen::Matrix3d m;
  m << 1 + c[0], c[3], c[5], c[3], 1 + c[1], c[4], c[5], c[4], 1 + c[2];
  return m;
}

/// J_p = 1 / √det C_p⁻¹, or 1 where that is within `unit` of it (plastic flow alone: round-off).
double plastic_volume_of(const Eigen::Matrix3d& Cp_inv, double unit) {
  const double jp = 1 / std::sqrt(Cp_inv.determinant());
  return std::abs(jp - 1) > unit ? jp : 1.0;
}

/// A symmetric tensor (its symmetric part) into those slots, less the identity.
void store(const Eigen::Matrix3d& m, double* c) {
  c[0] = m(0, 0) - 1;
  c[1] = m(1, 1) - 1;
  c[2] = m(2, 2) - 1;
  c[3] = 0.5 * (m(0, 1) + m(1, 0));
  c[4] = 0.5 * (m(1, 2) + m(2, 1));
  c[5] = 0.5 * (m(2, 0) + m(0, 2));
}
}  // namespace

J2Plasticity::J2Plasticity(const MaterialData& data, double dt)
    : flow_(make_flow_stress(data)),
      dt_(dt),
      temperature_(data.temperature),
      heating_(data.heat_capacity > 0 ? data.taylor_quinney / data.heat_capacity : 0.0),
      frozen_(flow_->rate_dependent() && !(dt > 0)) {
  const LinearElastic e(data.E, data.nu);
  G_ = e.mu();
  K_ = e.lambda() + 2.0 * G_ / 3.0;
  elastic_ = e.tangent3d();
}

FlowStressPoint J2Plasticity::yield_stress(double alpha, double increment, double rise) const {
  FlowStressPoint p = flow_->at(alpha, dt_ > 0 ? increment / dt_ : 0.0, temperature_ + rise);
  p.d_strain += dt_ > 0 ? p.d_rate / dt_ : 0.0;  // along Δα: the rate moves with it
  return p;
}

double J2Plasticity::plastic_increment(double q, double alpha_n, double rise) const {
  double dg = 0.0, lo = 0.0, hi = q / (3.0 * G_);  // the root lies between: σ_y > 0
  for (int it = 0; it < 100; ++it) {
    const FlowStressPoint y = yield_stress(alpha_n + dg, dg, rise);
    const double r = q - 3.0 * G_ * dg - y.stress;
    const double next = dg + r / (3.0 * G_ + y.d_strain);
    if (std::abs(r) <= 1e-13 * q) return next;
    (r > 0 ? lo : hi) = dg;
    dg = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  return dg;
}

void J2Plasticity::update(const Deformation& d, const double* committed, double* trial, Voigt6& stress,
                          Tangent6& tangent) const {
  const Eigen::Map<const Voigt6> ep_n(committed);
  const double alpha_n = committed[kAlpha], rise = committed[kHeat];
  stress = elastic_ * (d.strain - ep_n);  // elastic trial
  tangent = elastic_;
  Eigen::Map<Voigt6> ep(trial);
  ep = ep_n;
  trial[kAlpha] = alpha_n;
  trial[kHeat] = rise;
  Voigt6 s = stress;
  const double p = stress.head<3>().sum() / 3.0;
  s.head<3>().array() -= p;
  const double q = std::sqrt(1.5 * contract(s));  // von Mises of the trial stress
  const double y0 = yield_stress(alpha_n, 0, rise).stress;
  if (frozen_ || q - y0 <= 1e-12 * y0) return;
  // Δγ from q − 3G Δγ − σ_y(α_n + Δγ) = 0 (one Newton step for linear hardening)
  const double dg = plastic_increment(q, alpha_n, rise);
  if (!(dg > 0.0) || !std::isfinite(dg))
    throw std::runtime_error("the J2 return mapping found no plastic increment (von Mises trial stress " +
                             std::to_string(q) + ", flow stress " + std::to_string(y0) + ", α " +
                             std::to_string(alpha_n) + ", temperature " + std::to_string(temperature_ + rise) + ")");
  const Voigt6 n = s / std::sqrt(contract(s));  // unit normal, tensor components
  const double scale = 1.0 - 3.0 * G_ * dg / q;
  stress.head<3>() = s.head<3>() * scale + Voigt6::Constant(p).head<3>();
  stress.tail<3>() = s.tail<3>() * scale;
  // plastic strain increment Δγ N, N = (3/2) s / q = sqrt(3/2) n; engineering shears twice the tensor ones
  Voigt6 dep = std::sqrt(1.5) * dg * n;
  dep.tail<3>() *= 2.0;
  ep = ep_n + dep;
  trial[kAlpha] = alpha_n + dg;
  const FlowStressPoint y = yield_stress(alpha_n + dg, dg, rise);
  if (heating_ > 0)  // the plastic work ∫ τ_y dα over the step (trapezoid, at the step's rate), a share β as heat
    trial[kHeat] = rise + heating_ * 0.5 * (yield_stress(alpha_n, dg, rise).stress + y.stress) * dg;
  const double H = y.d_strain;
  tangent = elastic_ - (6.0 * G_ * G_ * dg / q) * deviatoric_projector() +
            6.0 * G_ * G_ * (dg / q - 1.0 / (3.0 * G_ + H)) * (n * n.transpose());
}

void J2Plasticity::update_finite(const Eigen::Matrix3d& F, const double* committed, double* trial, Voigt6& tau,
                                 FiniteTangent* tangent) const {
  const Eigen::Matrix3d Cp_inv = cp_inverse(committed);
  Deformation d;
  const Spectrum b = spectrum(F * Cp_inv * F.transpose());  // elastic trial left Cauchy–Green tensor
  d.strain = log_strain(b);
  double log_committed[kStateSize] = {0, 0, 0, 0, 0, 0, committed[kAlpha], committed[kHeat]}, log_trial[kStateSize];
  Tangent6 modulus;
  update(d, log_committed, log_trial, tau, modulus);
  // a reference moved to a configuration under elastic strain (rebase_state) holds a plastic volume J_p ≠ 1: the
  // stress per reference volume is J_p times Hencky's on b_e (J σ = J_p J_e σ)
  if (const double jp = plastic_volume_of(Cp_inv, kUnitVolume); jp != 1.0) {
    tau *= jp;
    modulus *= jp;
  }
  if (tangent) *tangent = {modulus, b};
  std::copy(committed, committed + kStateSize, trial);
  trial[kAlpha] = log_trial[kAlpha];
  trial[kHeat] = log_trial[kHeat];
  if (log_trial[kAlpha] == committed[kAlpha]) return;  // elastic: C_p unchanged
  // ε_e = ε_e trial − Δε_p, coaxial with b (Δε_p ∝ the trial deviator), so b_e = exp(2 ε_e) = Q diag(λ e^(−2 Δε_p,k))
  // Qᵀ with Δε_p,k its principal values on b's eigenvectors
  const Eigen::Matrix3d dep = strain_tensor(Eigen::Map<const Voigt6>(log_trial));
  const Eigen::Vector3d dep_principal = (b.vectors.transpose() * dep * b.vectors).diagonal();
  const Eigen::Matrix3d be = compose(b, b.values.cwiseProduct((-2 * dep_principal).array().exp().matrix()));
  const Eigen::Matrix3d Finv = F.inverse();
  store(Finv * be * Finv.transpose(), trial);
}

double J2Plasticity::plastic_volume(const double* c) const { return plastic_volume_of(cp_inverse(c), kUnitVolume); }

void J2Plasticity::rebase_state(const Eigen::Matrix3d& F, double* c) const {
  store(F * cp_inverse(c) * F.transpose(), c);
}

}  // namespace rollsim
