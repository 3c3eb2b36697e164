#include "fem/SolidElement.h"

#include <cmath>
#include <vector>

namespace rollsim {

namespace {

template <int D>
constexpr double natural(int node, int axis) {
  // Q4: (-1,-1) (1,-1) (1,1) (-1,1); H8: same square at z = -1 then at z = +1
  constexpr int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  if (axis == 0) return sx[node % 4];
  if (axis == 1) return sy[node % 4];
  return node < 4 ? -1.0 : 1.0;
}

/// Shape function values and derivatives with respect to natural coordinates at xi.
template <int D>
void shape(const double* xi, Eigen::Matrix<double, SolidElement<D>::NN, 1>& N,
           Eigen::Matrix<double, D, SolidElement<D>::NN>& dN) {
  constexpr int NN = SolidElement<D>::NN;
  const double scale = D == 2 ? 0.25 : 0.125;
  for (int a = 0; a < NN; ++a) {
    double f[D];
    for (int i = 0; i < D; ++i) f[i] = 1.0 + natural<D>(a, i) * xi[i];
    double prod = scale;
    for (int i = 0; i < D; ++i) prod *= f[i];
    N(a) = prod;
    for (int i = 0; i < D; ++i) {
      double d = scale * natural<D>(a, i);
      for (int k = 0; k < D; ++k)
        if (k != i) d *= f[k];
      dN(i, a) = d;
    }
  }
}

template <int D>
struct GaussData {
  Eigen::Matrix<double, SolidElement<D>::NS, SolidElement<D>::NDOF> B;
  Eigen::Matrix<double, 1, SolidElement<D>::NDOF> bvol;
  double dv;  // det J * weight
};

/// Strain-displacement matrices at every Gauss point (B-bar applied when asked). False if det J <= 0.
template <int D>
bool gauss_B(const typename SolidElement<D>::Coords& x, Formulation f,
             std::array<GaussData<D>, SolidElement<D>::NGP>& g) {
  constexpr int NN = SolidElement<D>::NN, NGP = SolidElement<D>::NGP;
  const double q = 1.0 / std::sqrt(3.0);
  Eigen::Matrix<double, 1, SolidElement<D>::NDOF> bbar = Eigen::Matrix<double, 1, SolidElement<D>::NDOF>::Zero();
  double vol = 0.0;
  for (int p = 0; p < NGP; ++p) {
    double xi[3];
    for (int i = 0; i < D; ++i) xi[i] = q * natural<D>(p, i);
    Eigen::Matrix<double, NN, 1> N;
    Eigen::Matrix<double, D, NN> dNxi;
    shape<D>(xi, N, dNxi);
    const Eigen::Matrix<double, D, D> J = dNxi * x.transpose();  // J(i,k) = d x_k / d xi_i
    const double detJ = J.determinant();
    if (!(detJ > 0.0)) return false;
    const Eigen::Matrix<double, D, NN> dN = J.inverse() * dNxi;  // d N_a / d x_k
    auto& B = g[p].B;
    B.setZero();
    for (int a = 0; a < NN; ++a) {
      for (int i = 0; i < D; ++i) {
        B(i, D * a + i) = dN(i, a);
        g[p].bvol(D * a + i) = dN(i, a);
      }
      if constexpr (D == 2) {
        B(3, 2 * a) = dN(1, a);
        B(3, 2 * a + 1) = dN(0, a);
      } else {
        B(3, 3 * a) = dN(1, a);
        B(3, 3 * a + 1) = dN(0, a);
        B(4, 3 * a + 1) = dN(2, a);
        B(4, 3 * a + 2) = dN(1, a);
        B(5, 3 * a) = dN(2, a);
        B(5, 3 * a + 2) = dN(0, a);
      }
    }
    g[p].dv = detJ;  // unit Gauss weights
    bbar += g[p].bvol * detJ;
    vol += detJ;
  }
  if (f == Formulation::BBar) {
    bbar /= vol;
    // replace the dilatational part of each B by the element mean: B += m (bbar - bvol) / 3
    for (int p = 0; p < NGP; ++p)
      for (int r = 0; r < 3; ++r) g[p].B.row(r) += (bbar - g[p].bvol) / 3.0;
  }
  return true;
}

/// The material's tangent in the element's strain components (plane strain: xx, yy, zz, xy).
template <int D>
Eigen::Matrix<double, SolidElement<D>::NS, SolidElement<D>::NS> tangent(const Material& m) {
  return m.initial_tangent().template topLeftCorner<SolidElement<D>::NS, SolidElement<D>::NS>();
}

}  // namespace

template <int D>
auto SolidElement<D>::shape_integrals(const Coords& x) -> Eigen::Matrix<double, NN, 1> {
  const double q = 1.0 / std::sqrt(3.0);
  Eigen::Matrix<double, NN, 1> N, sum = Eigen::Matrix<double, NN, 1>::Zero();
  Eigen::Matrix<double, D, NN> dNxi;
  for (int p = 0; p < NGP; ++p) {
    double xi[3] = {0, 0, 0};
    for (int i = 0; i < D; ++i) xi[i] = q * natural<D>(p, i);
    shape<D>(xi, N, dNxi);
    sum += N * (dNxi * x.transpose()).determinant();  // unit Gauss weights
  }
  return sum;
}

template <int D>
auto SolidElement<D>::gauss_shape() -> const Eigen::Matrix<double, NGP, NN>& {
  static const Eigen::Matrix<double, NGP, NN> at = [] {
    const double q = 1.0 / std::sqrt(3.0);
    Eigen::Matrix<double, NGP, NN> m;
    Eigen::Matrix<double, NN, 1> N;
    Eigen::Matrix<double, D, NN> dNxi;
    for (int p = 0; p < NGP; ++p) {
      double xi[3] = {0, 0, 0};
      for (int i = 0; i < D; ++i) xi[i] = q * natural<D>(p, i);
      shape<D>(xi, N, dNxi);
      m.row(p) = N.transpose();
    }
    return m;
  }();
  return at;
}

template <int D>
bool SolidElement<D>::gradients(const Coords& x, std::array<Gradients, NGP>& dN, std::array<double, NGP>& dv,
                                Gradients& centre) {
  const double q = 1.0 / std::sqrt(3.0);
  Eigen::Matrix<double, NN, 1> N;
  Eigen::Matrix<double, D, NN> dNxi;
  for (int p = 0; p <= NGP; ++p) {  // the Gauss points, then the centre
    double xi[3] = {0, 0, 0};
    if (p < NGP)
      for (int i = 0; i < D; ++i) xi[i] = q * natural<D>(p, i);
    shape<D>(xi, N, dNxi);
    const Eigen::Matrix<double, D, D> J = dNxi * x.transpose();
    const double detJ = J.determinant();
    if (!(detJ > 0.0)) return false;
    (p < NGP ? dN[p] : centre) = J.inverse() * dNxi;
    if (p < NGP) dv[p] = detJ;  // unit Gauss weights
  }
  return true;
}

template <int D>
void SolidElement<D>::stiffness(const Coords& x, const Material& mat, Formulation f, Stiffness& Ke) {
  std::array<GaussData<D>, NGP> g;
  Ke.setZero();
  if (!gauss_B<D>(x, f, g)) return;  // inverted elements are rejected when the model is built
  const auto C = tangent<D>(mat);
  for (int p = 0; p < NGP; ++p) Ke.noalias() += g[p].B.transpose() * (C * g[p].dv) * g[p].B;
}

template <int D>
bool SolidElement<D>::stresses_and_force(const Coords& x, const Material& mat, Formulation f, const Dofs& ue,
                                         std::array<Stress6, NGP>& out, Dofs& fe, const double* committed) {
  std::array<GaussData<D>, NGP> g;
  fe.setZero();
  if (!gauss_B<D>(x, f, g)) return false;
  const int ns = mat.state_size();
  std::vector<double> initial, trial(static_cast<size_t>(ns));
  if (!committed && ns > 0) {
    initial.assign(static_cast<size_t>(NGP * ns), 0.0);
    committed = initial.data();
  }
  Deformation d;  // ε in all six components (plane strain: yz = zx = 0)
  Voigt6 stress;
  Tangent6 C;
  for (int p = 0; p < NGP; ++p) {
    d.strain.template head<NS>() = g[p].B * ue;
    mat.update(d, ns ? committed + p * ns : nullptr, ns ? trial.data() : nullptr, stress, C);
    fe.noalias() += g[p].B.transpose() * (stress.template head<NS>() * g[p].dv);
    for (int c = 0; c < 6; ++c) out[p][c] = stress(c);
  }
  return true;
}

template <int D>
bool SolidElement<D>::tangent_and_force(const Coords& x, const Material& mat, Formulation f, const Dofs& ue,
                                        const double* committed, double* trial, Stiffness* Ke, Dofs& fe) {
  std::array<GaussData<D>, NGP> g;
  fe.setZero();
  if (Ke) Ke->setZero();
  if (!gauss_B<D>(x, f, g)) return false;
  const int ns = mat.state_size();
  Deformation d;
  Voigt6 stress;
  Tangent6 C;
  for (int p = 0; p < NGP; ++p) {
    d.strain.template head<NS>() = g[p].B * ue;
    mat.update(d, ns ? committed + p * ns : nullptr, ns ? trial + p * ns : nullptr, stress, C);
    fe.noalias() += g[p].B.transpose() * (stress.template head<NS>() * g[p].dv);
    if (Ke) Ke->noalias() += g[p].B.transpose() * (C.template topLeftCorner<NS, NS>() * g[p].dv) * g[p].B;
  }
  return true;
}

template <int D>
double SolidElement<D>::extrapolate_to_node(const std::array<double, NGP>& gp, int node) {
  double xi[3];
  for (int i = 0; i < D; ++i) xi[i] = std::sqrt(3.0) * natural<D>(node, i);
  Eigen::Matrix<double, NN, 1> N;
  Eigen::Matrix<double, D, NN> dN;
  shape<D>(xi, N, dN);
  double v = 0.0;
  for (int p = 0; p < NGP; ++p) v += N(p) * gp[p];
  return v;
}

template <int D>
void SolidElement<D>::shape_at(const double* xi, Eigen::Matrix<double, NN, 1>& N, Eigen::Matrix<double, D, NN>& dN) {
  shape<D>(xi, N, dN);
}

template struct SolidElement<2>;
template struct SolidElement<3>;

}  // namespace rollsim
