// The finite-strain kernel: its tangent is the derivative of its internal force (elastic and plastic states at 20 %
// strain, full and F-bar, Q4 and H8); a rigid rotation of a stressed element rotates its stresses and forces and
// changes nothing else (objectivity); a rigid motion alone gives no force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../../common/SaturatingSteel.h"
#include "fem/FiniteStrainElement.h"

namespace test_finite_strain_element {

using namespace rollsim;

namespace {
MaterialData plastic() { return rollsim::testing::saturating_steel(); }

template <int D>
typename SolidElement<D>::Coords unit_element() {
  typename SolidElement<D>::Coords x;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (int a = 0; a < SolidElement<D>::NN; ++a) {
    const int bits[3] = {a % 4 == 1 || a % 4 == 2, a % 4 >= 2, a >= 4};
    for (int i = 0; i < D; ++i) x(i, a) = bits[i] + jitter(rng);
  }
  return x;
}

template <int D>
typename SolidElement<D>::Dofs random_dofs(double scale, int seed) {
  typename SolidElement<D>::Dofs u;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> r(-1, 1);
  for (int i = 0; i < SolidElement<D>::NDOF; ++i) u(i) = scale * r(rng);
  return u;
}

template <int D>
void check_tangent(const MaterialData& data, Formulation f) {
  using El = SolidElement<D>;
  using FS = FiniteStrainElement<D>;
  const auto mat = make_material(data);
  const auto x = unit_element<D>();
  const typename El::Dofs ue = random_dofs<D>(0.1, 5);
  const int n = El::NGP * mat->state_size();
  std::vector<double> committed(static_cast<size_t>(n), 0.0), trial(committed.size() + 1);
  typename El::Stiffness K;
  typename El::Dofs f0, fp, fm;
  ASSERT_TRUE(FS::tangent_and_force(x, *mat, f, ue, committed.data(), trial.data(), &K, f0));
  if (data.plastic()) {
    double alpha = 0;
    for (int p = 0; p < El::NGP; ++p) alpha += trial[p * mat->state_size() + mat->equivalent_plastic_strain_index()];
    EXPECT_GT(alpha, 0.0);
  }
  typename El::Stiffness fd;
  const double h = 1e-6;
  for (int j = 0; j < El::NDOF; ++j) {
    typename El::Dofs up = ue, um = ue;
    up(j) += h;
    um(j) -= h;
    FS::tangent_and_force(x, *mat, f, up, committed.data(), trial.data(), nullptr, fp);
    FS::tangent_and_force(x, *mat, f, um, committed.data(), trial.data(), nullptr, fm);
    fd.col(j) = (fp - fm) / (2 * h);
  }
  EXPECT_LE((K - fd).norm(), 1e-5 * K.norm()) << D << "D, formulation " << static_cast<int>(f);
}

/// Rotation by `angle` about z (2D) or about the axis (1, 2, 3) (3D).
template <int D>
Eigen::Matrix<double, D, D> rotation(double angle) {
  if constexpr (D == 2)
    return Eigen::Rotation2Dd(angle).toRotationMatrix();
  else
    return Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
}
}  // namespace

TEST(FiniteStrainElement, TangentEqualsCentralDifferencesOfTheInternalForce) {
  MaterialData elastic{200e3, 0.3};
  for (Formulation f : {Formulation::Full, Formulation::BBar})
    for (const MaterialData& m : {elastic, plastic()}) {
      check_tangent<2>(m, f);
      check_tangent<3>(m, f);
    }
}

template <int D>
void check_objectivity() {
  using El = SolidElement<D>;
  const auto mat = make_material(plastic());
  const auto X = unit_element<D>();
  const typename El::Dofs u = random_dofs<D>(0.05, 9);
  const Eigen::Matrix<double, D, D> R = rotation<D>(1.1);
  typename El::Dofs u_rot;  // x' = R (X + u): u' = R (X + u) − X
  for (int a = 0; a < El::NN; ++a) {
    const Eigen::Matrix<double, D, 1> xa = X.col(a) + u.template segment<D>(a * D);
    u_rot.template segment<D>(a * D) = R * xa - X.col(a);
  }
  const int n = El::NGP * mat->state_size();
  std::vector<double> c(static_cast<size_t>(n), 0.0), t1(c.size()), t2(c.size());
  typename El::Dofs f1, f2;
  std::array<typename El::Stress6, El::NGP> s1, s2;
  ASSERT_TRUE(
      FiniteStrainElement<D>::tangent_and_force(X, *mat, Formulation::BBar, u, c.data(), t1.data(), nullptr, f1, &s1));
  ASSERT_TRUE(FiniteStrainElement<D>::tangent_and_force(X, *mat, Formulation::BBar, u_rot, c.data(), t2.data(), nullptr,
                                                        f2, &s2));
  for (int a = 0; a < El::NN; ++a)  // nodal forces turn with the body
    EXPECT_LE((f2.template segment<D>(a * D) - R * f1.template segment<D>(a * D)).norm(), 1e-9 * f1.norm());
  for (int p = 0; p < El::NGP; ++p) {  // principal stresses unchanged, plastic state unchanged
    auto principal = [](const typename El::Stress6& s) {
      Eigen::Matrix3d m;
      m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
      return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues().eval();
    };
    EXPECT_LE((principal(s1[p]) - principal(s2[p])).norm(), 1e-9 * principal(s1[p]).norm());
  }
  const int alpha = mat->equivalent_plastic_strain_index();
  for (int p = 0; p < El::NGP; ++p) {
    EXPECT_GT(t1[p * mat->state_size() + alpha], 0.0);
    EXPECT_NEAR(t1[p * mat->state_size() + alpha], t2[p * mat->state_size() + alpha], 1e-12);
  }
}

TEST(FiniteStrainElement, RigidRotationOfAStressedElementIsObjective) {
  check_objectivity<2>();
  check_objectivity<3>();
}

TEST(FiniteStrainElement, RigidMotionGivesNoForce) {
  using El = SolidElement<3>;
  const auto mat = make_material(plastic());
  const auto X = unit_element<3>();
  const Eigen::Matrix3d R = rotation<3>(2.5);
  El::Dofs u, f;
  for (int a = 0; a < El::NN; ++a) u.segment<3>(a * 3) = R * X.col(a) - X.col(a) + Eigen::Vector3d(3, -1, 2);
  std::vector<double> c(static_cast<size_t>(El::NGP * mat->state_size()), 0.0), t(c.size());
  ASSERT_TRUE(FiniteStrainElement<3>::tangent_and_force(X, *mat, Formulation::Full, u, c.data(), t.data(), nullptr, f));
  EXPECT_LT(f.norm(), 1e-8);
}

}  // namespace test_finite_strain_element
