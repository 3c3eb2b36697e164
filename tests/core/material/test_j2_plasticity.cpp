// J2 plasticity, small strain: the closed form of monotonic simple shear with linear hardening, the stress on the
// yield surface after a return, the consistent tangent against central differences of the return map, and the
// state left alone by an elastic step.
#include <gtest/gtest.h>

#include <cmath>

#include "material/J2Plasticity.h"
#include "material/LinearElastic.h"

namespace test_j2_plasticity {

using namespace rollsim;

namespace {
MaterialData steel(double sat = 0.0, double delta = 0.0) {
  MaterialData m;
  m.E = 206.9e3;
  m.nu = 0.29;
  m.yield_stress = 450.0;
  m.hardening_modulus = 129.24;
  m.saturation_stress = sat;
  m.saturation_exponent = delta;
  return m;
}

/// Hot carbon steel (Shida's law, 0.2 % C) at `T` °C.
MaterialData hot_steel(double T = 1100) {
  MaterialData m;
  m.E = 1.2e5;
  m.nu = 0.3;
  m.flow_stress = {"shida", {{"carbon", 0.2}}};
  m.temperature = T;
  return m;
}

struct Point {
  double committed[J2Plasticity::kStateSize] = {};
  double trial[J2Plasticity::kStateSize] = {};
  void commit() { std::copy(trial, trial + J2Plasticity::kStateSize, committed); }
};

/// dσ/dε of m's return from `committed` at d, by central differences of step 1e-8.
Tangent6 central_differences(const J2Plasticity& m, const Deformation& d, const double* committed) {
  const double h = 1e-8;
  Tangent6 fd, unused;
  Voigt6 s_plus, s_minus;
  for (int j = 0; j < 6; ++j) {
    Deformation dp = d, dm = d;
    dp.strain(j) += h;
    dm.strain(j) -= h;
    double scratch[J2Plasticity::kStateSize];
    m.update(dp, committed, scratch, s_plus, unused);
    m.update(dm, committed, scratch, s_minus, unused);
    fd.col(j) = (s_plus - s_minus) / (2 * h);
  }
  return fd;
}
}  // namespace

TEST(J2Plasticity, SimpleShearMatchesTheClosedForm) {
  const MaterialData data = steel();
  const J2Plasticity m(data);
  const double G = data.E / (2 * (1 + data.nu)), H = data.hardening_modulus, s0 = data.yield_stress;
  Point pt;
  Deformation d;
  Voigt6 stress;
  Tangent6 tangent;
  for (int step = 1; step <= 40; ++step) {
    const double gamma = 2e-4 * step;
    d.strain << 0, 0, 0, gamma, 0, 0;
    m.update(d, pt.committed, pt.trial, stress, tangent);
    pt.commit();
    const double tau =
        G * gamma <= s0 / std::sqrt(3.0) ? G * gamma : G * (H * gamma + std::sqrt(3.0) * s0) / (H + 3 * G);
    EXPECT_NEAR(stress(3), tau, 1e-9 * tau) << "gamma " << gamma;
    EXPECT_NEAR(stress.head<3>().norm() + stress.tail<2>().norm(), 0.0, 1e-9 * tau);
  }
  EXPECT_GT(pt.committed[J2Plasticity::kAlpha], 0.0);
  EXPECT_NEAR(pt.committed[J2Plasticity::kAlpha], pt.committed[3] / std::sqrt(3.0), 1e-15);
}

TEST(J2Plasticity, ReturnEndsOnTheYieldSurface) {
  const J2Plasticity m(steel(715.0, 16.93));
  Point pt;
  Deformation d;
  d.strain << 4e-3, -1e-3, 5e-4, 3e-3, -2e-3, 1e-3;
  Voigt6 stress;
  Tangent6 tangent;
  m.update(d, pt.committed, pt.trial, stress, tangent);
  const double alpha = pt.trial[J2Plasticity::kAlpha];
  ASSERT_GT(alpha, 0.0);
  EXPECT_NEAR(von_mises(stress.data()), m.yield_stress(alpha).stress, 1e-10 * m.yield_stress(alpha).stress);
  // plastic flow is isochoric
  EXPECT_NEAR(pt.trial[0] + pt.trial[1] + pt.trial[2], 0.0, 1e-15);
}

TEST(J2Plasticity, ConsistentTangentEqualsCentralDifferences) {
  const J2Plasticity m(steel(715.0, 16.93));
  Point pt;  // a plastic history first, so that the committed state is not zero
  Deformation d;
  Voigt6 stress;
  Tangent6 tangent;
  d.strain << 2e-3, -5e-4, 0, 1e-3, 0, 5e-4;
  m.update(d, pt.committed, pt.trial, stress, tangent);
  pt.commit();
  d.strain << 5e-3, -2e-3, 1e-3, 3e-3, -1e-3, 2e-3;
  m.update(d, pt.committed, pt.trial, stress, tangent);
  ASSERT_GT(pt.trial[J2Plasticity::kAlpha], pt.committed[J2Plasticity::kAlpha]);
  const Tangent6 fd = central_differences(m, d, pt.committed);
  EXPECT_LE((tangent - fd).norm(), 1e-6 * tangent.norm());
  EXPECT_LT((tangent - tangent.transpose()).norm(), 1e-10 * tangent.norm()) << "associative flow: symmetric";
}

TEST(J2Plasticity, ElasticStepKeepsTheState) {
  const J2Plasticity m(steel());
  Point pt;
  pt.committed[0] = 1e-3;
  pt.committed[1] = pt.committed[2] = -5e-4;
  pt.committed[J2Plasticity::kAlpha] = 1e-3;
  Deformation d;
  d.strain << 1e-3, -5e-4, -5e-4, 0, 0, 0;  // the plastic strain itself: zero stress
  Voigt6 stress;
  Tangent6 tangent;
  m.update(d, pt.committed, pt.trial, stress, tangent);
  EXPECT_LT(stress.norm(), 1e-9);
  for (int i = 0; i < J2Plasticity::kStateSize; ++i) EXPECT_EQ(pt.trial[i], pt.committed[i]);
  EXPECT_EQ(m.name(), make_material(steel())->name());
}

TEST(J2Plasticity, RateDependentReturnEndsOnTheFlowStressAtItsRate) {
  const MaterialData data = hot_steel();
  const double dt = 0.02;
  const J2Plasticity m(data, dt);
  Point pt;
  pt.committed[J2Plasticity::kAlpha] = 0.1;
  Deformation d;
  d.strain << 6e-3, -3e-3, -3e-3, 1e-3, 0, 0;
  Voigt6 stress;
  Tangent6 tangent;
  m.update(d, pt.committed, pt.trial, stress, tangent);
  const double dalpha = pt.trial[J2Plasticity::kAlpha] - 0.1;
  ASSERT_GT(dalpha, 0.0);
  const double flow = make_flow_stress(data)->at(0.1 + dalpha, dalpha / dt, 1100).stress;
  EXPECT_NEAR(von_mises(stress.data()), flow, 1e-10 * flow);
  // the same step twice as slow flows at half the rate: a lower stress, more plastic strain
  const J2Plasticity slow(data, 2 * dt);
  Voigt6 slow_stress;
  Point slow_pt = pt;
  slow.update(d, slow_pt.committed, slow_pt.trial, slow_stress, tangent);
  EXPECT_LT(von_mises(slow_stress.data()), von_mises(stress.data()));
  EXPECT_GT(slow_pt.trial[J2Plasticity::kAlpha] - 0.1, dalpha);
}

TEST(J2Plasticity, RateDependentTangentEqualsCentralDifferences) {
  const J2Plasticity m(hot_steel(950), 0.05);
  Point pt;
  pt.committed[J2Plasticity::kAlpha] = 0.05;
  Deformation d;
  d.strain << 4e-3, -1e-3, -2e-3, 2e-3, -1e-3, 1e-3;
  Voigt6 stress;
  Tangent6 tangent;
  m.update(d, pt.committed, pt.trial, stress, tangent);
  ASSERT_GT(pt.trial[J2Plasticity::kAlpha], pt.committed[J2Plasticity::kAlpha]);
  const Tangent6 fd = central_differences(m, d, pt.committed);
  EXPECT_LE((tangent - fd).norm(), 1e-6 * tangent.norm());
}

TEST(J2Plasticity, WithoutTimeARateDependentStateIsFrozen) {
  const J2Plasticity m(hot_steel(), 0.0);  // as a stress recovery makes it: no time passes, nothing flows
  Point pt;
  Deformation d;
  d.strain << 6e-3, -3e-3, -3e-3, 0, 0, 0;
  Voigt6 stress;
  Tangent6 tangent;
  m.update(d, pt.committed, pt.trial, stress, tangent);
  EXPECT_EQ(pt.trial[J2Plasticity::kAlpha], 0.0);
  EXPECT_LT((tangent - LinearElastic(1.2e5, 0.3).tangent3d()).norm(), 1e-9 * tangent.norm());
}

}  // namespace test_j2_plasticity
