// Flow stress laws: Shida's value at a hand-computed point, every law's derivatives against central differences, the
// offsets, and the registry's schema (one variant per law).
#include <gtest/gtest.h>

#include <cmath>

#include "material/FlowStress.h"

namespace test_flow_stress {

using namespace rollsim;

namespace {
std::unique_ptr<FlowStress> law(const std::string& name, std::map<std::string, double> c) {
  MaterialData d;
  d.flow_stress = {name, std::move(c)};
  return make_flow_stress(d);
}

/// ∂σ/∂ε and ∂σ/∂ε̇ of `f` at (e, rate, T) against central differences, relative to σ.
void expect_derivatives(const FlowStress& f, double e, double rate, double T) {
  const FlowStressPoint p = f.at(e, rate, T);
  const double he = 1e-6 * e, hr = 1e-6 * rate;
  const double d_strain = (f.at(e + he, rate, T).stress - f.at(e - he, rate, T).stress) / (2 * he);
  const double d_rate = (f.at(e, rate + hr, T).stress - f.at(e, rate - hr, T).stress) / (2 * hr);
  EXPECT_NEAR(p.d_strain, d_strain, 1e-6 * std::abs(p.stress / e)) << "ε " << e << " ε̇ " << rate << " T " << T;
  EXPECT_NEAR(p.d_rate, d_rate, 1e-6 * std::abs(p.stress / rate)) << "ε " << e << " ε̇ " << rate << " T " << T;
}

const std::map<std::string, double> kHenselSpittel{
    {"A", 2800}, {"m1", -0.0027}, {"m2", 0.17},   {"m3", 0.13}, {"m4", -0.02},          {"m5", 2e-4},
    {"m6", 0.1}, {"m7", -0.6},    {"m8", 1.5e-5}, {"m9", 0.05}, {"strain_offset", 0.01}};
}  // namespace

TEST(FlowStress, ShidaAtTheAustenitePointOfHandArithmetic) {
  // C 0.2 %, 1100 °C: T = 1.373 > T_d = 0.95 · 0.61 / 0.52 = 1.1144; σ_T = 0.28 exp(5/1.373 − 0.01/0.25) = 10.2645
  // kgf/mm²; at ε = 0.2 (f = 1) and ε̇ = 10 /s ((ε̇/10)^m = 1): 10.2645 · 9.80665 = 100.66 MPa
  const auto shida = law("shida", {{"carbon", 0.2}, {"strain_offset", 0.0}, {"rate_offset", 0.0}});
  EXPECT_NEAR(shida->at(0.2, 10, 1100).stress, 100.6607, 1e-3);
  // m = (−0.019 · 0.2 + 0.126) · 1.373 + 0.075 · 0.2 − 0.05 = 0.13278: ten times the rate, 10^m = 1.3584 times the
  // stress
  EXPECT_NEAR(shida->at(0.2, 100, 1100).stress / 100.6607, std::pow(10, 0.1327806), 1e-6);
  EXPECT_TRUE(shida->rate_dependent());
}

// Shida's strain term f = 1.3 (ε/0.2)^n − 0.3 (ε/0.2) peaks at ε* = 0.2 (1.3 n / 0.3)^(1/(1−n)) (0.489 for 0.2 % C)
// and would reach zero at ε ≈ 2.27: a rolled surface's shear took a second pass there (a negative flow stress, the
// return mapping failing). Beyond its peak it is held: steady-state flow, its strain derivative 0.
TEST(FlowStress, ShidaHoldsItsPeakBeyondIt) {
  const auto shida = law("shida", {{"carbon", 0.2}, {"strain_offset", 0.0}, {"rate_offset", 0.0}});
  const double n = 0.41 - 0.07 * 0.2, peak = 0.2 * std::pow(1.3 * n / 0.3, 1 / (1 - n));
  EXPECT_NEAR(peak, 0.489, 1e-3);
  const double top = shida->at(peak, 3, 1000).stress;
  EXPECT_GT(top, shida->at(0.9 * peak, 3, 1000).stress);
  for (double e : {1.0, 2.3, 5.0}) {
    EXPECT_DOUBLE_EQ(shida->at(e, 3, 1000).stress, top) << e;
    EXPECT_EQ(shida->at(e, 3, 1000).d_strain, 0.0) << e;
  }
}

TEST(FlowStress, DerivativesEqualCentralDifferences) {
  const auto shida = law("shida", {{"carbon", 0.45}});
  for (double T : {800.0, 1150.0})  // below and above T_d (1.02 of 1000 K for 0.45 % C)
    for (double e : {0.05, 0.3, 0.6}) expect_derivatives(*shida, e, 3.0, T);
  const auto hs = law("hensel_spittel", kHenselSpittel);
  for (double e : {0.05, 0.4}) expect_derivatives(*hs, e, 5.0, 1050);
  const auto jc = law("johnson_cook", {{"A", 90}, {"B", 290}, {"n", 0.3}, {"C", 0.025}, {"m", 1.0}});
  for (double e : {0.01, 0.5}) expect_derivatives(*jc, e, 40.0, 600);
}

TEST(FlowStress, TheOffsetsAreAddedBeforeTheFormula) {
  const auto offset = law("shida", {{"carbon", 0.2}, {"strain_offset", 0.02}, {"rate_offset", 0.1}});
  const auto bare = law("shida", {{"carbon", 0.2}, {"strain_offset", 0.0}, {"rate_offset", 0.0}});
  const FlowStressPoint at_zero = offset->at(0.0, 0.0, 1100), shifted = bare->at(0.02, 0.1, 1100);
  EXPECT_DOUBLE_EQ(at_zero.stress, shifted.stress);
  EXPECT_DOUBLE_EQ(at_zero.d_strain, shifted.d_strain);
  EXPECT_DOUBLE_EQ(at_zero.d_rate, shifted.d_rate);
  // at zero strain and rate: a positive flow stress with finite, positive slopes (no kink for Newton to stall on)
  EXPECT_GT(at_zero.stress, 0.0);
  EXPECT_GT(at_zero.d_strain, 0.0);
  EXPECT_GT(at_zero.d_rate, 0.0);
  EXPECT_TRUE(std::isfinite(at_zero.d_strain) && std::isfinite(at_zero.d_rate));
}

TEST(FlowStress, RateDependenceFollowsTheCoefficients) {
  EXPECT_FALSE(law("johnson_cook", {{"A", 200}})->rate_dependent());
  EXPECT_TRUE(law("johnson_cook", {{"A", 200}, {"C", 0.01}})->rate_dependent());
  std::map<std::string, double> hs = kHenselSpittel;
  hs["m3"] = hs["m8"] = 0;
  EXPECT_FALSE(law("hensel_spittel", hs)->rate_dependent());
  MaterialData hardening;
  hardening.yield_stress = 100, hardening.hardening_modulus = 300;
  const auto h = make_flow_stress(hardening);
  EXPECT_FALSE(h->rate_dependent());
  EXPECT_DOUBLE_EQ(h->at(0.1, 50, 900).stress, 130.0);
}

TEST(FlowStress, EveryLawIsAVariantOfTheSchema) {
  const ObjectSchema& s = flow_stress_schema();
  EXPECT_EQ(s.discriminator, "law");
  ASSERT_EQ(s.variants.size(), flow_stress_laws().size());
  for (const FlowStressLaw& l : flow_stress_laws()) EXPECT_EQ(s.variants.at(l.name), l.schema);
  EXPECT_EQ(find_flow_stress_law("nope"), nullptr);
  EXPECT_THROW(law("johnson_cook", {}), std::invalid_argument) << "A has no default";
}

}  // namespace test_flow_stress
