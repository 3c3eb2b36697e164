// Carrying integration-point state between meshes (fem/StateTransfer): a constant is carried exactly, a point that
// did not move keeps its value, no value leaves the old range, a smooth field's integral is kept; the finite-strain J2
// state read on the current configuration gives, at F = I, the stress it gave at F.
#include <gtest/gtest.h>

#include <cmath>

#include "fem/Assembler.h"
#include "fem/SolidElement.h"
#include "fem/StateTransfer.h"
#include "material/J2Plasticity.h"
#include "mesh/StructuredBlock.h"

namespace test_state_transfer {

using namespace rollsim;

namespace {
Mesh block(int nx, int ny) {
  BlockSpec s;
  s.n = {nx, ny, 1};
  s.size = {4.0, 2.0, 1.0};
  return make_block(s);
}

/// `f` at every integration point of `m` (one value each).
template <class F>
std::vector<double> at_points(const Mesh& m, F f) {
  std::vector<double> v;
  const auto& N = SolidElement<2>::gauss_shape();
  for (int e = 0; e < m.num_elements(); ++e)
    for (int p = 0; p < 4; ++p) {
      double x = 0, y = 0;
      for (int a = 0; a < 4; ++a)
        x += N(p, a) * m.nodes[m.element(e)[a]][0], y += N(p, a) * m.nodes[m.element(e)[a]][1];
      v.push_back(f(x, y));
    }
  return v;
}

/// The block's inner nodes shifted (the same region, another spread).
Mesh shifted(const Mesh& m) {
  Mesh to = m;
  for (auto& p : to.nodes)
    if (p[0] > 0 && p[0] < 4 && p[1] > 0 && p[1] < 2)
      p[0] += 0.15 * std::sin(M_PI * p[1] / 2), p[1] += 0.1 * std::sin(M_PI * p[0] / 4);
  return to;
}
}  // namespace

TEST(StateTransfer, AConstantIsCarriedExactlyAndTwoComponentsApart) {
  const Mesh from = block(8, 4), to = shifted(from);
  std::vector<double> values;
  for (double v : at_points(from, [](double, double) { return 0.25; })) values.insert(values.end(), {v, -3.0});
  const std::vector<double> out = transfer_points(from, from.nodes, values, 2, to);
  ASSERT_EQ(out.size(), values.size());
  for (size_t i = 0; i < out.size(); i += 2) {
    EXPECT_NEAR(out[i], 0.25, 1e-13);
    EXPECT_NEAR(out[i + 1], -3.0, 1e-13);
  }
}

TEST(StateTransfer, APointThatDidNotMoveKeepsItsOwnValue) {
  const Mesh m = block(6, 3);
  std::vector<double> values;
  for (size_t p = 0; p < static_cast<size_t>(m.num_elements()) * 4; ++p) values.push_back(std::sin(1.0 + p));
  const std::vector<double> out = transfer_points(m, m.nodes, values, 1, m);
  for (size_t p = 0; p < values.size(); ++p) EXPECT_NEAR(out[p], values[p], 1e-12) << "point " << p;
}

TEST(StateTransfer, NoNewExtremesAndTheIntegralKept) {
  const Mesh from = block(16, 8), to = shifted(from);
  const auto bump = [](double x, double y) { return std::exp(-((x - 2) * (x - 2) + (y - 1) * (y - 1))); };
  const std::vector<double> values = at_points(from, bump);
  const std::vector<double> out = transfer_points(from, from.nodes, values, 1, to);
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  for (double v : out) {
    EXPECT_GE(v, *lo - 1e-14);
    EXPECT_LE(v, *hi + 1e-14);
  }
  const double before = integral(from, from.nodes, values, 1, 0), after = integral(to, to.nodes, out, 1, 0);
  EXPECT_NEAR(after / before, 1.0, 0.01);
  EXPECT_NE(after, before);  // points that moved get their neighbours' values: not a copy
}

TEST(StateTransfer, NodalValuesInterpolatedWherePointsMoved) {
  const Mesh from = block(8, 4), to = shifted(from);
  std::vector<double> linear;
  for (const auto& p : from.nodes) linear.push_back(3 * p[0] - 2 * p[1] + 1);
  const std::vector<double> out = transfer_nodes(from, from.nodes, linear, to);
  for (int n = 0; n < to.num_nodes(); ++n) EXPECT_NEAR(out[n], 3 * to.nodes[n][0] - 2 * to.nodes[n][1] + 1, 1e-11);
}

TEST(StateTransfer, NodalValuesKeepTheirIntegralAcrossASteepLayer) {
  // a chilled skin at the top (y = 2): 200 K colder at the surface, gone within 0.2 mm, and the inner nodes moved
  // across it: interpolated alone, the field loses its kinks and with them part of its integral
  const Mesh from = block(16, 8), to = shifted(from);
  const auto field = [](double y) { return 1100 - 200 * std::exp(-(2 - y) / 0.2); };
  std::vector<double> before;
  for (const auto& p : from.nodes) before.push_back(field(p[1]));
  const std::vector<double> out = transfer_nodes(from, from.nodes, before, to);
  const auto integral_of = [](const Mesh& m, const std::vector<double>& nodal) {
    return integral(m, m.nodes, point_values(m, nodal.data()), 1, 0);
  };
  const double deficit = 1100 * 8.0 - integral_of(from, before);  // the skin's, against a block at 1100 throughout
  ASSERT_GT(deficit, 10.0);
  EXPECT_NEAR(integral_of(to, out), integral_of(from, before), 1e-3 * deficit);
  const auto [lo, hi] = std::minmax_element(before.begin(), before.end());
  for (double v : out) EXPECT_TRUE(v >= *lo && v <= *hi) << v;
}

TEST(StateTransfer, TheCurrentJ2StateGivesTheSameStressAtTheIdentity) {
  MaterialData d;
  d.E = 200000, d.nu = 0.3, d.yield_stress = 250, d.hardening_modulus = 2000;
  const J2Plasticity j2(d);
  Eigen::Matrix3d F;
  F << 1.1, 0.15, 0, -0.05, 0.88, 0, 0, 0, 1;  // plastic: well past yield
  std::vector<double> committed(J2Plasticity::kStateSize, 0.0), trial(J2Plasticity::kStateSize);
  Voigt6 tau;
  j2.update_finite(F, committed.data(), trial.data(), tau, nullptr);
  ASSERT_GT(trial[J2Plasticity::kAlpha], 0.01);
  // the state after the step, then the same F again: elastic, τ unchanged
  std::vector<double> rebased = trial, again(J2Plasticity::kStateSize);
  j2.rebase_state(F, rebased.data());
  Voigt6 tau_identity;
  j2.update_finite(Eigen::Matrix3d::Identity(), rebased.data(), again.data(), tau_identity, nullptr);
  // the same Cauchy stress: τ per the new reference's volume is τ / J of the old
  const Voigt6 sigma = tau / F.determinant();
  EXPECT_LT((tau_identity - sigma).norm(), 1e-9 * sigma.norm());
  EXPECT_NEAR(again[J2Plasticity::kAlpha], trial[J2Plasticity::kAlpha], 1e-12);
}

}  // namespace test_state_transfer
