// The Newton element kernel: its tangent is the derivative of its internal force (central differences), for
// elastic and plastic states, full and B-bar integration, Q4 and H8; and an elastic material gives the linear
// element's stiffness and K u.
#include <gtest/gtest.h>

#include <random>

#include "../../common/SaturatingSteel.h"
#include "fem/SolidElement.h"

namespace test_element_tangent {

using namespace rollsim;

namespace {
MaterialData plastic() { return rollsim::testing::saturating_steel(); }

template <int D>
typename SolidElement<D>::Coords distorted() {
  typename SolidElement<D>::Coords x;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (int a = 0; a < SolidElement<D>::NN; ++a) {
    const int bits[3] = {a % 4 == 1 || a % 4 == 2, a % 4 >= 2, a >= 4};
    for (int i = 0; i < D; ++i) x(i, a) = bits[i] + jitter(rng);
  }
  return x;
}

template <int D>
void check_tangent(Formulation f, double strain_scale) {
  using El = SolidElement<D>;
  const auto mat = make_material(plastic());
  const auto x = distorted<D>();
  typename El::Dofs ue;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < El::NDOF; ++i) ue(i) = strain_scale * u(rng);
  const int n = El::NGP * mat->state_size();
  std::vector<double> committed(static_cast<size_t>(n), 0.0), trial(committed.size());
  typename El::Stiffness K, unused;
  typename El::Dofs f0, fp, fm;
  ASSERT_TRUE(El::tangent_and_force(x, *mat, f, ue, committed.data(), trial.data(), &K, f0));
  double alpha = 0;
  for (int p = 0; p < El::NGP; ++p) alpha += trial[p * mat->state_size() + mat->equivalent_plastic_strain_index()];
  if (strain_scale > 1e-2) EXPECT_GT(alpha, 0.0) << "the state is plastic";
  typename El::Stiffness fd;
  const double h = 1e-7 * strain_scale;
  for (int j = 0; j < El::NDOF; ++j) {
    typename El::Dofs up = ue, um = ue;
    up(j) += h;
    um(j) -= h;
    El::tangent_and_force(x, *mat, f, up, committed.data(), trial.data(), nullptr, fp);
    El::tangent_and_force(x, *mat, f, um, committed.data(), trial.data(), nullptr, fm);
    fd.col(j) = (fp - fm) / (2 * h);
  }
  EXPECT_LE((K - fd).norm(), 1e-6 * K.norm()) << D << "D, formulation " << static_cast<int>(f);
}
}  // namespace

TEST(ElementTangent, EqualsCentralDifferencesOfTheInternalForce) {
  for (Formulation f : {Formulation::Full, Formulation::BBar})
    for (double scale : {1e-5, 1e-2}) {  // elastic, then well into the plastic range
      check_tangent<2>(f, scale);
      check_tangent<3>(f, scale);
    }
}

TEST(ElementTangent, ElasticMaterialGivesTheLinearElement) {
  using El = SolidElement<3>;
  const auto mat = make_material(MaterialData{1000, 0.25});
  const auto x = distorted<3>();
  El::Dofs ue = El::Dofs::LinSpaced(-0.01, 0.02), fe;
  El::Stiffness K, K_linear;
  ASSERT_TRUE(El::tangent_and_force(x, *mat, Formulation::BBar, ue, nullptr, nullptr, &K, fe));
  El::stiffness(x, *mat, Formulation::BBar, K_linear);
  EXPECT_LE((K - K_linear).norm(), 1e-12 * K.norm());
  EXPECT_LE((fe - K_linear * ue).norm(), 1e-12 * fe.norm());
}

}  // namespace test_element_tangent
