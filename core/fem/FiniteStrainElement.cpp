#include "fem/FiniteStrainElement.h"

#include <cmath>

#include "material/KirchhoffModulus.h"

namespace rollsim {

namespace {
using Matrix3 = Eigen::Matrix3d;

/// F = I + ∂u/∂X (3 × 3; plane strain: F33 = 1) from the reference gradients and the element displacements.
template <int D>
Matrix3 deformation_gradient(const typename SolidElement<D>::Gradients& dN, const typename SolidElement<D>::Dofs& ue) {
  Matrix3 F = Matrix3::Identity();
  for (int a = 0; a < SolidElement<D>::NN; ++a)
    for (int i = 0; i < D; ++i)
      for (int k = 0; k < D; ++k) F(i, k) += ue(a * D + i) * dN(k, a);
  return F;
}

/// F-bar: (J_0 / J)^{1/D} on the D × D block.
template <int D>
Matrix3 f_bar(const Matrix3& F, double J0) {
  Matrix3 Fb = F;
  const double ratio = J0 / F.topLeftCorner<D, D>().determinant();
  Fb.topLeftCorner<D, D>() *= D == 2 ? std::sqrt(ratio) : std::cbrt(ratio);
  return Fb;
}
}  // namespace

template <int D>
bool FiniteStrainElement<D>::tangent_and_force(const typename El::Coords& X, const Material& mat, Formulation f,
                                               const typename El::Dofs& ue, const double* committed, double* trial,
                                               typename El::Stiffness* Ke, typename El::Dofs& fe,
                                               std::array<Stress6, El::NGP>* stresses) {
  typename El::Geometry reference;
  if (!El::gradients(X, reference)) {
    fe.setZero();
    if (Ke) Ke->setZero();
    return false;
  }
  return tangent_and_force(reference, mat, f, ue, committed, trial, Ke, fe, stresses);
}

template <int D>
bool FiniteStrainElement<D>::tangent_and_force(const typename El::Geometry& reference, const Material& mat,
                                               Formulation f, const typename El::Dofs& ue, const double* committed,
                                               double* trial, typename El::Stiffness* Ke, typename El::Dofs& fe,
                                               std::array<Stress6, El::NGP>* stresses, PointUpdates* memo,
                                               PointMemo mode) {
  constexpr int NN = El::NN, NGP = El::NGP;
  const bool reuse = memo && mode == PointMemo::reuse && memo->valid && memo->ue == ue;
  if (memo && !reuse) {
    memo->valid = false;  // until every point is in
    memo->ue = ue;
  }
  const std::array<typename El::Gradients, NGP>& dN0 = reference.dN;
  const std::array<double, NGP>& dv0 = reference.dv;
  const typename El::Gradients& centre0 = reference.centre;
  fe.setZero();
  if (Ke) Ke->setZero();
  const bool fbar = f == Formulation::BBar;
  const Matrix3 Fc = deformation_gradient<D>(centre0, ue);
  const double Jc = Fc.topLeftCorner<D, D>().determinant();
  if (!(Jc > 0.0)) return false;
  const typename El::Gradients gc = Fc.topLeftCorner<D, D>().inverse().transpose() * centre0;  // ∂N/∂x at centre
  const int ns = mat.state_size();
  for (int p = 0; p < NGP; ++p) {
    const Matrix3 F = deformation_gradient<D>(dN0[p], ue);
    const double J = F.topLeftCorner<D, D>().determinant();
    if (!(J > 0.0)) return false;
    const Matrix3 Fb = fbar ? f_bar<D>(F, Jc) : F;
    const double* c = ns ? committed + p * ns : nullptr;
    Voigt6 tau_v;
    FiniteTangent ft;
    if (reuse) {
      tau_v = memo->tau[p];
      ft = memo->with[p];
    } else {
      mat.update_finite(Fb, c, ns ? trial + p * ns : nullptr, tau_v, Ke || memo ? &ft : nullptr);
    }
    if (memo && !reuse) memo->tau[p] = tau_v, memo->with[p] = ft;
    const Matrix3 tau = stress_tensor(tau_v);
    // f = ∫ σ(F̄) ∇_x N dv over the current volume (dv = J dV0): the reference-volume stress is (J / J̄) τ(F̄)
    const double ratio = fbar ? J / Jc : 1.0;
    const typename El::Gradients g = F.topLeftCorner<D, D>().inverse().transpose() * dN0[p];  // ∂N/∂x
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < D; ++i) fe(a * D + i) += ratio * tau.row(i).head<D>().dot(g.col(a)) * dv0[p];
    if (stresses)
      for (int k = 0; k < 6; ++k) (*stresses)[p][k] = tau_v(k) / (Fb.topLeftCorner<D, D>().determinant());
    if (!Ke) continue;
    const Eigen::Matrix<double, 9, 9> A = kirchhoff_modulus(ft, D);  // ∂τ_ij / ∂(∇_x u)_ml of τ((I + ∇_x u) F̄)
    // δτ (column-major) for δu = e_m N_b, in column b·D + m. With F-bar, δF̄ F̄⁻¹ gains (div_c δu − div δu) / D × I
    // and δ(J / J̄) = (J / J̄)(div δu − div_c δu).
    Eigen::Matrix<double, 9, NN * D> dtau;
    Eigen::Matrix<double, 9, 1> q = Eigen::Matrix<double, 9, 1>::Zero();
    for (int r = 0; r < D; ++r) q += A.col(r * 3 + r);
    const Eigen::Map<const Eigen::Matrix<double, 9, 1>> tau9(tau.data());
    for (int b = 0; b < NN; ++b)
      for (int m = 0; m < D; ++m) {
        auto column = dtau.col(b * D + m);
        column.noalias() = A.middleCols<D>(m * 3) * g.col(b);
        if (fbar) column += (gc(m, b) - g(m, b)) * (q / D - tau9);
      }
    // K_(ai)(bm) = (J / J̄) ∫ (Σ_j ∂N_a/∂x_j δτ_ij − Σ_j τ_ij ∂N_b/∂x_j ∂N_a/∂x_m) dV0; the first term, for one i,
    // is gᵀ (NN × D) times the rows δτ_ij, j < D (D × NN·D): D products per entry instead of a 9-long sum of zeros
    const double w = ratio * dv0[p];
    for (int i = 0; i < D; ++i) {
      Eigen::Matrix<double, D, NN * D> rows_i;
      for (int j = 0; j < D; ++j) rows_i.row(j) = dtau.row(j * 3 + i);
      const Eigen::Matrix<double, NN, NN* D> first = w * (g.transpose() * rows_i);
      for (int a = 0; a < NN; ++a) Ke->row(a * D + i) += first.row(a);
    }
    const Eigen::Matrix<double, D, NN> tau_g = tau.topLeftCorner<D, D>() * g;
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < D; ++i)
        for (int b = 0; b < NN; ++b)
          for (int m = 0; m < D; ++m) (*Ke)(a * D + i, b * D + m) -= w * g(m, a) * tau_g(i, b);
  }
  if (memo && !reuse) memo->valid = true;
  return true;
}

template struct FiniteStrainElement<2>;
template struct FiniteStrainElement<3>;

}  // namespace rollsim
