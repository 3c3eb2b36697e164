// No locking: a smooth rigid punch (half-width b = 1, prescribed settlement) on a perfectly plastic plane-strain
// block reaches Prandtl's limit pressure 2k(1 + π/2), k = σ_y / √3, within 2 % with B-bar (small strain) and F-bar
// (finite strain), where full integration locks and overshoots by more than 10 %.
#include <gtest/gtest.h>

#include <cmath>

#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_prandtl_punch {

using namespace rollsim;
using json = nlohmann::json;

namespace {
/// Limit pressure over k of the half model (symmetry at x = 0), 24 × 12 elements of 0.25.
double pressure_over_k(const std::string& formulation, const std::string& kinematics) {
  const double sy = 10.0;
  const json j = {{"name", "punch"},
                  {"dimension", 2},
                  {"materials", {{{"name", "m"}, {"E", 1e4}, {"nu", 0.3}, {"yield_stress", sy}}}},
                  {"bodies",
                   {{{"name", "block"},
                     {"material", "m"},
                     {"formulation", formulation},
                     {"kinematics", kinematics},
                     {"mesh", {{"type", "block"}, {"nx", 24}, {"ny", 12}, {"lx", 6.0}, {"ly", 3.0}}},
                     {"node_sets", {{{"name", "punch"}, {"box_min", {0.0, 3.0}}, {"box_max", {1.0, 3.0}}}}}}}},
                  {"boundary_conditions",
                   {{{"type", "displacement"}, {"body", "block"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
                    {{"type", "displacement"}, {"body", "block"}, {"set", "xmin"}, {"ux", 0.0}},
                    {{"type", "displacement"}, {"body", "block"}, {"set", "punch"}, {"uy", -0.03}}}},
                  {"analysis", {{"increments", 15}}}};
  const Project p = parse_project(j.dump(), "punch.json");
  const Model m = build_model(p);
  const Results r = run_project(p, m);
  EXPECT_EQ(r.status.status, Status::converged) << r.status.message;
  double force = 0;
  for (int n : m.bodies[0].mesh.node_sets.at("punch")) force -= r.bodies[0].nodal_force[n * 2 + 1];
  return force / 1.0 / (sy / std::sqrt(3.0));
}
}  // namespace

TEST(PrandtlPunch, BBarAndFBarReachTheLimitLoadWhereFullIntegrationLocks) {
  const double prandtl = 2 + M_PI;
  const double bbar = pressure_over_k("bbar", "small"), fbar = pressure_over_k("bbar", "finite");
  const double full = pressure_over_k("full", "small");
  EXPECT_NEAR(bbar / prandtl, 1.0, 0.02) << bbar;
  EXPECT_NEAR(fbar / prandtl, 1.0, 0.02) << fbar;
  EXPECT_GT(full / prandtl, 1.10) << "full integration locks: " << full;
}

}  // namespace test_prandtl_punch
