// Heat conduction with temperature-dependent properties (materials[].thermal_table, analysis/HeatConduction): a block
// whose ρc rises with temperature cools in air as its lumped ODE (integrated here with RK4 at tiny steps), first
// order in time; a bar whose k falls with temperature carries its steady Kirchhoff profile, ∫k dT linear along it
// (the profile a constant k would make straight); a temperature leaving the table is a warning in summary.json.
// Units: mm, N, s, K.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../../common/HeatBlocks.h"
#include "../../common/RunJson.h"
#include "io/Summary.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_heat_conduction_tables {

using namespace rollsim;
using json = nlohmann::json;
using testing_support::heat_block;
using testing_support::held_at_rest;
using testing_support::run_json;

namespace {
constexpr double kAir = 20;

// --- a lumped block whose ρc rises linearly with temperature -------------------------------------------------------

constexpr double kHot = 1000, kH = 0.05, kDuration = 200;  // h [kW/(m² K)], t [s]
constexpr double kPerimeter = 40, kArea = 100;             // the 10 × 10 mm block

/// ρc(T) of the block: 3.6 MPa/K at 20 °C rising linearly to 5.4 at 1000 °C.
double rho_c(double T) { return 3.6 + 1.8 * (T - 20) / 980; }

json lumped_block(int steps, const json& table) {
  json air = json::array();
  for (const char* s : {"xmin", "xmax", "ymin", "ymax"})
    air.push_back({{"body", "block"}, {"surface", s}, {"convection", kH}});
  const json steel = {{"name", "steel"},        {"E", 2e5},           {"nu", 0.3}, {"conductivity", 1e4},
                      {"thermal_table", table}, {"temperature", kHot}};
  return {{"name", "lumped"},
          {"dimension", 2},
          {"materials", {steel}},
          {"bodies", {heat_block("block", "steel", 4, 4, 10, 10)}},
          {"boundary_conditions", held_at_rest("block")},
          {"heat", {{"ambient_temperature", kAir}, {"air", air}}},
          {"analysis", {{"increments", steps}, {"duration", kDuration}}}};
}

const json kRisingCapacity = {{"temperature", {20.0, 1000.0}}, {"heat_capacity", {3.6, 5.4}}};

/// ρc(T) A dT/dt = −h P (T − T_air), RK4 over `steps` steps.
double lumped_ode(double duration, int steps) {
  const auto rate = [](double T) { return -kH * kPerimeter * (T - kAir) / (rho_c(T) * kArea); };
  double T = kHot;
  const double dt = duration / steps;
  for (int i = 0; i < steps; ++i) {
    const double a = rate(T), b = rate(T + dt / 2 * a), c = rate(T + dt / 2 * b), d = rate(T + dt * c);
    T += dt / 6 * (a + 2 * b + 2 * c + d);
  }
  return T;
}

double block_mean(int steps) {
  const Results r = run_json(lumped_block(steps, kRisingCapacity));
  EXPECT_EQ(r.status.status, Status::converged) << r.status.message;
  return r.bodies[0].nodal_temperature.mean();
}
}  // namespace

TEST(HeatConductionTables, ABlockWhoseHeatCapacityRisesCoolsAsItsLumpedOde) {
  const double exact = lumped_ode(kDuration, 200000);
  EXPECT_NEAR(exact, lumped_ode(kDuration, 100000), 1e-9 * kHot) << "the reference has converged";
  // the table matters: ρc held at its hot value (or its cold one) ends elsewhere, far beyond the tolerance below
  const double drop = kHot - exact,
               hot_constant = kAir + (kHot - kAir) * std::exp(-kH * kPerimeter * kDuration / (rho_c(kHot) * kArea));
  EXPECT_GT(std::abs(hot_constant - exact), 0.05 * drop) << hot_constant << " " << exact;
  const double T200 = block_mean(200);
  EXPECT_NEAR(T200, exact, 0.005 * drop) << "semi-implicit backward Euler, 200 steps";
  const double e10 = std::abs(block_mean(10) - exact), e20 = std::abs(block_mean(20) - exact);
  EXPECT_NEAR(std::log2(e10 / e20), 1.0, 0.15) << e10 << " " << e20;
  std::printf("rho_c(T) lumped: %.6g (RK4 %.6g), error %.2e of the drop; 10 / 20 steps %.3g / %.3g K, order %.2f\n",
              T200, exact, std::abs(T200 - exact) / drop, e10, e20, std::log2(e10 / e20));
}

namespace {
// --- a bar whose k falls linearly with temperature, steady between a hot reservoir and the air ----------------------

constexpr double kBarLength = 10, kReservoir = 1000, kHc = 1e3, kBarH = 50;
constexpr double kK0 = 50, kSlope = -25.0 / 1200;  // k(T) = 50 − 25 T / 1200 W/(m K), T in °C

double k_of(double T) { return kK0 + kSlope * T; }
/// The Kirchhoff transform θ(T) = ∫_0^T k dT.
double theta(double T) { return kK0 * T + kSlope / 2 * T * T; }
/// θ⁻¹: the root of kSlope/2 T² + kK0 T − θ = 0 near the table's range.
double from_theta(double th) { return (-kK0 + std::sqrt(kK0 * kK0 + 2 * kSlope * th)) / kSlope; }

/// The bar (body `bar`, ny elements on y ∈ [0, L], its ymin cooled by air) under a reservoir (body `reservoir`, one
/// element on [L, 2L], ρc 1e7: it stays at kReservoir) pressed onto it through a conductance kHc.
json bar_under_reservoir(int ny, double duration, int steps) {
  const json bar = {{"name", "bar"},
                    {"E", 2e5},
                    {"nu", 0.3},
                    {"heat_capacity", 4.5},
                    {"temperature", 500.0},
                    {"thermal_table", {{"temperature", {0.0, 1200.0}}, {"conductivity", {k_of(0), k_of(1200)}}}}};
  const json reservoir = {
      {"name", "reservoir"},      {"E", 2e5}, {"nu", 0.3}, {"conductivity", 1e4}, {"heat_capacity", 1e7},
      {"temperature", kReservoir}};
  json bcs = held_at_rest("bar");
  bcs.push_back({{"type", "displacement"}, {"body", "reservoir"}, {"set", "xmin"}, {"ux", 0.0}});
  bcs.push_back({{"type", "displacement"}, {"body", "reservoir"}, {"set", "ymax"}, {"uy", -1e-5}});
  return {{"name", "bar"},
          {"dimension", 2},
          {"materials", {bar, reservoir}},
          {"bodies",
           {heat_block("bar", "bar", 1, ny, 1, kBarLength),
            heat_block("reservoir", "reservoir", 1, 1, 1, kBarLength, kBarLength)}},
          {"boundary_conditions", bcs},
          {"contacts",
           {{{"name", "interface"},
             {"type", "frictionless"},
             {"slave_body", "reservoir"},
             {"slave_surface", "ymin"},
             {"master_body", "bar"},
             {"master_surface", "ymax"},
             {"conductance", kHc}}}},
          {"heat",
           {{"ambient_temperature", kAir}, {"air", {{{"body", "bar"}, {"surface", "ymin"}, {"convection", kBarH}}}}}},
          {"analysis", {{"increments", steps}, {"duration", duration}}}};
}

/// The steady flux q through a bar of length L between the air (T_air, h) and a reservoir at Tr (h_c):
/// q L = θ(Tr − q/h_c) − θ(T_air + q/h), by bisection.
double steady_flux(double Tr, double L) {
  double lo = 0, hi = kK0 * (Tr - kAir) / L;
  for (int i = 0; i < 200; ++i) {
    const double q = (lo + hi) / 2;
    (theta(Tr - q / kHc) - theta(kAir + q / kBarH) > q * L ? lo : hi) = q;
  }
  return (lo + hi) / 2;
}
}  // namespace

TEST(HeatConductionTables, ABarWhoseConductivityFallsCarriesItsKirchhoffProfile) {
  const int ny = 10;
  const json j = bar_under_reservoir(ny, 300, 60);
  const Project p = parse_project(j.dump(), "table.json");
  const Model m = build_model(p);
  const Results r = run_project(p, m);
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  const Eigen::VectorXd& T = r.bodies[0].nodal_temperature;
  const Eigen::VectorXd& u = r.bodies[0].displacement;
  const double Tr = (r.bodies[1].nodal_temperature[0] + r.bodies[1].nodal_temperature[1]) / 2;
  const auto y = [&](int n) { return m.bodies[0].mesh.nodes[static_cast<size_t>(n)][1] + u[2 * n + 1]; };
  const double L = y(2 * ny) - y(0), q = steady_flux(Tr, L), Tb = kAir + q / kBarH;
  double worst = 0;
  for (int n = 0; n < T.size(); ++n)
    worst = std::max(worst, std::abs(T[n] - from_theta(theta(Tb) + q * (y(n) - y(0)))));
  const double span = Tr - kAir;
  EXPECT_LT(worst, 1e-4 * span) << "k linear in T, k at each element's mean: the steady nodal values are exact";
  // a constant k would make the profile straight; k smaller where hot steepens it toward the reservoir, and its
  // middle sits far below the chord between its ends
  const double middle = (T[ny] + T[ny + 1]) / 2, chord = (T[0] + T[2 * ny]) / 2;
  EXPECT_GT(chord - middle, 0.03 * span) << middle << " " << chord;
  std::printf("k(T) bar: flux %.6g, worst nodal error %.2e of the span; middle %.2f K below the straight profile\n", q,
              worst / span, chord - middle);
}

TEST(HeatConductionTables, ATemperatureLeavingTheTableIsAWarningInTheSummary) {
  // the table holds from 600 °C: the block ends near 420 °C, its ρc held at the 600 °C value below it
  const json narrow = {{"temperature", {600.0, 1000.0}}, {"heat_capacity", {4.7, 5.4}}};
  const Project p = parse_project(lumped_block(20, narrow).dump(), "table.json");
  const Model m = build_model(p);
  EXPECT_TRUE(m.warnings.empty()) << "it starts within the table";
  const Results r = run_project(p, m);
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  const json warnings = make_summary(m, r, RunInfo{"table", "direct"}).value("warnings", json::array());
  ASSERT_EQ(warnings.size(), 1u) << warnings.dump();
  const std::string w = warnings[0];
  EXPECT_NE(w.find("body 'block' (material 'steel')"), std::string::npos) << w;
  EXPECT_NE(w.find("thermal_table's 600 °C to 1000 °C"), std::string::npos) << w;
  // within the table: no warning
  const Project within = parse_project(lumped_block(20, kRisingCapacity).dump(), "table.json");
  const Model mw = build_model(within);
  EXPECT_FALSE(make_summary(mw, run_project(within, mw), RunInfo{"table", "direct"}).contains("warnings"));
}

}  // namespace test_heat_conduction_tables
