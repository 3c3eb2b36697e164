#include "fem/FiniteStrainElement.h"

#include <cmath>
#include <vector>

namespace rollsim {

namespace {
using Matrix3 = Eigen::Matrix3d;

Matrix3 tensor(const Voigt6& s) {
  Matrix3 t;
  t << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
  return t;
}

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
  Fb.topLeftCorner<D, D>() *= std::pow(J0 / F.topLeftCorner<D, D>().determinant(), 1.0 / D);
  return Fb;
}
}  // namespace

template <int D>
bool FiniteStrainElement<D>::tangent_and_force(const typename El::Coords& X, const Material& mat, Formulation f,
                                               const typename El::Dofs& ue, const double* committed, double* trial,
                                               typename El::Stiffness* Ke, typename El::Dofs& fe,
                                               std::array<Stress6, El::NGP>* stresses) {
  constexpr int NN = El::NN, NGP = El::NGP;
  std::array<typename El::Gradients, NGP> dN0;
  std::array<double, NGP> dv0;
  typename El::Gradients centre0;
  fe.setZero();
  if (Ke) Ke->setZero();
  if (!El::gradients(X, dN0, dv0, centre0)) return false;
  const bool fbar = f == Formulation::BBar;
  const Matrix3 Fc = deformation_gradient<D>(centre0, ue);
  const double Jc = Fc.topLeftCorner<D, D>().determinant();
  if (!(Jc > 0.0)) return false;
  const typename El::Gradients gc = Fc.topLeftCorner<D, D>().inverse().transpose() * centre0;  // ∂N/∂x at centre
  const int ns = mat.state_size();
  std::vector<double> scratch(static_cast<size_t>(ns));
  for (int p = 0; p < NGP; ++p) {
    const Matrix3 F = deformation_gradient<D>(dN0[p], ue);
    const double J = F.topLeftCorner<D, D>().determinant();
    if (!(J > 0.0)) return false;
    const Matrix3 Fb = fbar ? f_bar<D>(F, Jc) : F;
    const double* c = ns ? committed + p * ns : nullptr;
    Voigt6 tau_v;
    mat.update_finite(Fb, c, ns ? trial + p * ns : nullptr, tau_v);
    const Matrix3 tau = tensor(tau_v);
    // f = ∫ σ(F̄) ∇_x N dv over the current volume (dv = J dV0): the reference-volume stress is (J / J̄) τ(F̄)
    const double ratio = fbar ? J / Jc : 1.0;
    const typename El::Gradients g = F.topLeftCorner<D, D>().inverse().transpose() * dN0[p];  // ∂N/∂x
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < D; ++i) fe(a * D + i) += ratio * tau.row(i).head<D>().dot(g.col(a)) * dv0[p];
    if (stresses)
      for (int k = 0; k < 6; ++k) (*stresses)[p][k] = tau_v(k) / (Fb.topLeftCorner<D, D>().determinant());
    if (!Ke) continue;
    // A(i,j,m,l) = ∂τ_ij / ∂(∇_x u)_ml by central differences of τ((I + h E_ml) F̄)
    Eigen::Matrix<double, 9, D * D> A;
    const double h = 1e-7;
    for (int m = 0; m < D; ++m)
      for (int l = 0; l < D; ++l) {
        Matrix3 E = Matrix3::Zero();
        E(m, l) = h;
        Voigt6 tp, tm;
        mat.update_finite((Matrix3::Identity() + E) * Fb, c, ns ? scratch.data() : nullptr, tp);
        mat.update_finite((Matrix3::Identity() - E) * Fb, c, ns ? scratch.data() : nullptr, tm);
        const Matrix3 dtau = (tensor(tp) - tensor(tm)) / (2 * h);
        A.col(m * D + l) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(dtau.data());
      }
    auto a_of = [&](int i, int j, int m, int l) { return A(j * 3 + i, m * D + l); };  // column-major dτ
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < D; ++i)
        for (int b = 0; b < NN; ++b)
          for (int m = 0; m < D; ++m) {
            double k = 0;
            for (int j = 0; j < D; ++j) {
              double dtau_ij = 0;  // δτ_ij for δu = e_m N_b
              for (int l = 0; l < D; ++l) dtau_ij += a_of(i, j, m, l) * g(l, b);
              if (fbar) {  // δF̄ F̄⁻¹ gains (div_c δu − div δu) / D × I; δ(J / J̄) = (J / J̄)(div δu − div_c δu)
                double q = 0;
                for (int r = 0; r < D; ++r) q += a_of(i, j, r, r);
                dtau_ij += q * (gc(m, b) - g(m, b)) / D + tau(i, j) * (g(m, b) - gc(m, b));
              }
              k += ratio * (g(j, a) * dtau_ij - tau(i, j) * g(m, a) * g(j, b));
            }
            (*Ke)(a * D + i, b * D + m) += k * dv0[p];
          }
  }
  return true;
}

template struct FiniteStrainElement<2>;
template struct FiniteStrainElement<3>;

}  // namespace rollsim
