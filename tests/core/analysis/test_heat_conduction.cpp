// Heat conduction staggered with the Newton analysis (analysis/HeatConduction), against closed forms: a block
// cooling in air with a uniform temperature (lumped), a semi-infinite body cooled by convection at its face (the erfc
// solution) with the observed orders in time and space, and two blocks pressed together through a contact
// conductance (their lumped exchange, and the interface temperature of two semi-infinite bodies in perfect contact).
// Units: mm, N, s, K.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../../common/HeatBlocks.h"
#include "../../common/RunJson.h"
#include "analysis/HeatConduction.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_heat_conduction {

using namespace rollsim;
using json = nlohmann::json;
using testing_support::heat_block;
using testing_support::held_at_rest;
using testing_support::run_json;

namespace {
json material(const std::string& name, double k, double rho_c, double T) {
  return {{"name", name}, {"E", 2e5}, {"nu", 0.3}, {"conductivity", k}, {"heat_capacity", rho_c}, {"temperature", T}};
}

/// One body, cooled by air of `h` on `surfaces`, over `duration` in `steps`.
json cooling(const json& body, const json& mat, const std::vector<std::string>& surfaces, double h, double duration,
             int steps) {
  json air = json::array();
  for (const std::string& s : surfaces) air.push_back({{"body", body["name"]}, {"surface", s}, {"convection", h}});
  return {{"name", "cooling"},
          {"dimension", 2},
          {"materials", {mat}},
          {"bodies", {body}},
          {"boundary_conditions", held_at_rest(body["name"])},
          {"heat", {{"ambient_temperature", 20.0}, {"air", air}}},
          {"analysis", {{"increments", steps}, {"duration", duration}}}};
}

constexpr double kT0 = 1000, kAir = 20;
constexpr double k = 30, rho_c = 4.5;  // hot steel: W/(m K), MPa/K
constexpr double alpha = k / rho_c;    // diffusivity [mm²/s]

/// The semi-infinite body at kT0 whose face x = 0 meets air at kAir through h from t = 0 (Carslaw & Jaeger §2.7).
double erfc_solution(double x, double t, double h) {
  const double s = std::sqrt(alpha * t), eta = x / (2 * s), b = h * s / k;
  const double theta = std::erfc(eta) - std::exp(h * x / k + b * b) * std::erfc(eta + b);
  return kT0 + (kAir - kT0) * theta;
}

/// Largest nodal error of the strip (`nx` elements over 40 mm, one across) at t = 1 s after `steps` steps, relative
/// to the temperature drop.
double strip_error(int nx, int steps) {
  const double h = 20;  // kW/(m² K): a roll's contact, h √(α t) / k ≈ 1.7
  const json j =
      cooling(heat_block("strip", "steel", nx, 1, 40, 1), material("steel", k, rho_c, kT0), {"xmin"}, h, 1.0, steps);
  const Project p = parse_project(j.dump(), "heat.json");
  const Model m = build_model(p);
  const Results r = run_project(p, m);
  EXPECT_EQ(r.status.status, Status::converged) << r.status.message;
  double worst = 0;
  for (int n = 0; n < m.bodies[0].mesh.num_nodes(); ++n)
    worst = std::max(worst, std::abs(r.bodies[0].nodal_temperature[n] -
                                     erfc_solution(m.bodies[0].mesh.nodes[static_cast<size_t>(n)][0], 1.0, h)));
  return worst / (kT0 - kAir);
}
}  // namespace

TEST(HeatConduction, ABlockCoolsInAirAsItsLumpedClosedForm) {
  // k large: the block stays uniform (Biot h L / k = 5e-5); T = T_air + (T0 − T_air) exp(−h P t / (ρc A))
  const double h = 0.05, duration = 200, rate = h * 40 / (rho_c * 100);
  const json j = cooling(heat_block("block", "steel", 4, 4, 10, 10), material("steel", 1e4, rho_c, kT0),
                         {"xmin", "xmax", "ymin", "ymax"}, h, duration, 200);
  const Results r = run_json(j);
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  const Eigen::VectorXd& T = r.bodies[0].nodal_temperature;
  ASSERT_EQ(T.size(), 25);
  const double exact = kAir + (kT0 - kAir) * std::exp(-rate * duration);
  EXPECT_LT(T.maxCoeff() - T.minCoeff(), 0.05) << "uniform";
  EXPECT_NEAR(T.mean(), exact, 0.005 * (kT0 - exact)) << "backward Euler, 200 steps";
  // first order in time: halving the step halves the error
  const auto error = [&](int steps) {
    json c = j;
    c["analysis"]["increments"] = steps;
    return std::abs(run_json(c).bodies[0].nodal_temperature.mean() - exact);
  };
  const double e10 = error(10), e20 = error(20);
  EXPECT_NEAR(std::log2(e10 / e20), 1.0, 0.15) << e10 << " " << e20;
  std::printf("lumped cooling: %.6g (exact %.6g); error 10 / 20 steps %.3g / %.3g, order %.2f\n", T.mean(), exact, e10,
              e20, std::log2(e10 / e20));
  // the cell field is its nodes' mean
  EXPECT_NEAR(r.bodies[0].temperature[0], T.mean(), 1e-2);
}

TEST(HeatConduction, ASemiInfiniteBodyCooledAtItsFaceFollowsTheErfcSolution) {
  const double fine = strip_error(160, 200);
  EXPECT_LT(fine, 0.005) << "within 0.5 % of the temperature drop";
  // space: second order (time fine)
  const double coarse_h = strip_error(20, 400), half_h = strip_error(40, 400);
  EXPECT_GT(std::log2(coarse_h / half_h), 1.6) << coarse_h << " " << half_h;
  // time: first order (mesh fine)
  const double coarse_t = strip_error(160, 10), half_t = strip_error(160, 20);
  EXPECT_NEAR(std::log2(coarse_t / half_t), 1.0, 0.25) << coarse_t << " " << half_t;
  std::printf(
      "erfc: 160 el / 200 steps %.2e; space 20 -> 40 el (400 steps) %.2e -> %.2e, order %.2f; time 10 -> 20 "
      "steps (160 el) %.2e -> %.2e, order %.2f\n",
      fine, coarse_h, half_h, std::log2(coarse_h / half_h), coarse_t, half_t, std::log2(coarse_t / half_t));
}

namespace {
/// The volume mean of a column of elements' nodal temperatures (two nodes per row): the end rows' nodes stand for
/// half an element each, the others for a whole one.
double column_mean(const Eigen::VectorXd& T) {
  const Eigen::Index n = T.size();
  return (T.sum() - 0.5 * (T[0] + T[1] + T[n - 2] + T[n - 1])) / static_cast<double>(n / 2 - 1) / 2;
}

/// Two bodies stacked, the hot one below: `lower` on y ∈ [0, ly], `upper` on [ly, 2 ly], 1 element across x, the
/// upper pressed down by 1e-3 mm onto the lower through a frictionless pair with conductance `hc`.
json pressed(int ny, double ly, const json& hot, const json& cold, double hc, double duration, int steps) {
  json bcs = held_at_rest("lower");
  bcs.push_back({{"type", "displacement"}, {"body", "upper"}, {"set", "xmin"}, {"ux", 0.0}});
  bcs.push_back({{"type", "displacement"}, {"body", "upper"}, {"set", "ymax"}, {"uy", -1e-3}});
  return {
      {"name", "pressed"},
      {"dimension", 2},
      {"materials", {hot, cold}},
      {"bodies", {heat_block("lower", hot["name"], 1, ny, 1, ly), heat_block("upper", cold["name"], 1, ny, 1, ly, ly)}},
      {"boundary_conditions", bcs},
      {"contacts",
       {{{"name", "interface"},
         {"type", "frictionless"},
         {"slave_body", "upper"},
         {"slave_surface", "ymin"},
         {"master_body", "lower"},
         {"master_surface", "ymax"},
         {"conductance", hc}}}},
      {"analysis", {{"increments", steps}, {"duration", duration}}}};
}
}  // namespace

TEST(HeatConduction, TwoBlocksPressedTogetherExchangeHeatThroughTheirConductance) {
  // k large, each block uniform: ΔT = ΔT0 exp(−h_c A (1/C1 + 1/C2) t), and C1 T1 + C2 T2 kept (no air)
  const double hc = 0.1, c1 = 4, c2 = 2, duration = 100;
  const Results r =
      run_json(pressed(4, 10, material("hot", 1e4, c1, kT0), material("cold", 1e4, c2, kAir), hc, duration, 400));
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  const double T1 = column_mean(r.bodies[0].nodal_temperature), T2 = column_mean(r.bodies[1].nodal_temperature);
  const double C1 = c1 * 10, C2 = c2 * 10;  // ρc V, 1 × 10 mm, unit thickness
  const double rate = hc * 1 * (1 / C1 + 1 / C2);
  EXPECT_NEAR(T1 - T2, (kT0 - kAir) * std::exp(-rate * duration), 0.005 * (T1 - T2));
  EXPECT_NEAR(C1 * T1 + C2 * T2, C1 * kT0 + C2 * kAir, 1e-9 * C1 * kT0) << "the link conserves the heat";
}

TEST(HeatConduction, TwoBodiesInPerfectContactMeetAtTheirEffusivityWeightedTemperature) {
  // semi-infinite bodies: the interface stays at (e1 T1 + e2 T2) / (e1 + e2), e = √(k ρc) (Carslaw & Jaeger §2.15)
  const json hot = material("hot", k, rho_c, kT0), cold = material("cold", 45, 3.6, kAir);
  const Results r = run_json(pressed(80, 20, hot, cold, 1e3, 1.0, 100));
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  const double e1 = std::sqrt(k * rho_c), e2 = std::sqrt(45 * 3.6), exact = (e1 * kT0 + e2 * kAir) / (e1 + e2);
  // the interface nodes: the lower body's top (nodes 160, 161 of 2 × 81) and the upper body's bottom (0, 1)
  const double lower = r.bodies[0].nodal_temperature[160], upper = r.bodies[1].nodal_temperature[0];
  EXPECT_NEAR(lower, exact, 0.01 * (kT0 - kAir)) << "h_c 1000: nearly perfect contact";
  EXPECT_NEAR(upper, exact, 0.01 * (kT0 - kAir));
  EXPECT_GT(lower, upper) << "the hot side stays warmer by q / h_c";
}

TEST(HeatConduction, ConductionWithoutTimeIsRefusedAtItsPath) {
  json j = cooling(heat_block("block", "steel", 2, 2, 10, 10), material("steel", 30, rho_c, kT0), {"xmin"}, 0.05, 1, 1);
  j["analysis"].erase("duration");
  try {
    parse_project(j.dump(), "heat.json");
    build_model(parse_project(j.dump(), "heat.json"));
    FAIL() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("analysis.duration"), std::string::npos) << e.what();
  }
  json no_capacity =
      cooling(heat_block("block", "steel", 2, 2, 10, 10), material("steel", 30, rho_c, kT0), {"xmin"}, 0.05, 1, 1);
  no_capacity["materials"][0].erase("heat_capacity");
  try {
    build_model(parse_project(no_capacity.dump(), "heat.json"));
    FAIL() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("materials[0].heat_capacity"), std::string::npos) << e.what();
  }
  json elastic_pair = pressed(2, 10, material("hot", 30, rho_c, kT0), material("cold", 30, rho_c, kAir), 10, 1, 1);
  elastic_pair["materials"][1].erase("conductivity");
  elastic_pair["materials"][1].erase("heat_capacity");
  try {
    build_model(parse_project(elastic_pair.dump(), "heat.json"));
    FAIL() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("contacts[0].conductance"), std::string::npos) << e.what();
  }
  json bad_surface =
      cooling(heat_block("block", "steel", 2, 2, 10, 10), material("steel", 30, rho_c, kT0), {"top"}, 0.05, 1, 1);
  try {
    build_model(parse_project(bad_surface.dump(), "heat.json"));
    FAIL() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("heat.air[0].surface"), std::string::npos) << e.what();
  }
}

}  // namespace test_heat_conduction
