// Frictionless cylinder on a block (plane strain) against Hertz, a = sqrt(4PR/(πE*)), p0 = 2P/(πa): under mesh
// refinement the FE half-width stays within half an element of a (its resolution), the peak nodal pressure within
// 2 % of p0, and the active set settles without cycling.
// The table printed here is the one in docs/VALIDATION.md.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_hertz {

using namespace rollsim;

namespace {
struct Row {
  double h, a, p0, a_hertz, p0_hertz;
  int iterations, active;
};

/// The sample with mesh size about h near the contact.
Row solve_at(double h) {
  std::ifstream in(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / "cylinder-indent-2d.json");
  json j = json::parse(in);
  const int nb = static_cast<int>(std::lround(1.5 / h)), na = static_cast<int>(std::lround(1.5708 / h)),
            nr = static_cast<int>(std::lround(0.9 / h));
  j["bodies"][0]["mesh"]["nx"] = nb;
  j["bodies"][0]["mesh"]["ny"] = nb;
  j["bodies"][1]["mesh"]["n_around"] = na;
  j["bodies"][1]["mesh"]["n_radial"] = nr;
  j["boundary_conditions"][3]["fy"] = -2.16 / (nr + 1);
  const Model model = build_model(parse_project(j.dump(), "hertz"));
  auto solver = make_solver("mixed", {1e-10, 1});
  const Results r = run_linear_static(model, *solver);
  EXPECT_EQ(to_string(r.status.status), std::string("converged"));
  const ContactResult& c = r.contacts.at(0);
  const double P = 2 * c.normal_force, R = 1.0, E = 1000.0, nu = 0.3;  // whole cylinder (half model)
  const double Estar = 1.0 / (2 * (1 - nu * nu) / E);
  const double a = std::sqrt(4 * P * R / (M_PI * Estar));
  return {h, c.measure, c.max_pressure, a, 2 * P / (M_PI * a), r.active_set_iterations, c.active_nodes};
}
}  // namespace

TEST(Hertz, HalfWidthAndPeakPressureConvergeUnderRefinement) {
  std::vector<Row> rows;
  for (const double h : {0.04, 0.02, 0.01}) rows.push_back(solve_at(h));
  std::printf(
      "| h | active nodes | active-set iterations | a (FE) | a (Hertz) | a error | p0 (FE) | p0 (Hertz) | p0 error |\n"
      "|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows)
    std::printf("| %.2f | %d | %d | %.4f | %.4f | %+.1f %% | %.2f | %.2f | %+.1f %% |\n", r.h, r.active, r.iterations,
                r.a, r.a_hertz, 100 * (r.a / r.a_hertz - 1), r.p0, r.p0_hertz, 100 * (r.p0 / r.p0_hertz - 1));
  for (const Row& r : rows) {
    EXPECT_LT(r.iterations, 15) << "the active set settles (no cycling), h = " << r.h;
    // the FE half-width is (k + 1/2) h for k + 1 active nodes: Hertz's a must lie within that resolution
    EXPECT_LT(std::abs(r.a - r.a_hertz), 0.6 * r.h) << "a within half an element, h = " << r.h;
    EXPECT_LT(std::abs(r.p0 / r.p0_hertz - 1), 0.02) << "peak pressure within 2 %, h = " << r.h;
  }
  EXPECT_GT(rows.back().active, 2 * rows.front().active) << "the contact zone is resolved by more nodes";
}

}  // namespace test_hertz
