// solver.mode `auto`: the mode of least predicted cost among direct, mixed and (a body partitioned) feti, from the
// partition table's cost model; run_project resolves it, reports it and runs the chosen mode unchanged.
#include "project/SolverChoice.h"
#include "solve/SolverStrategy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "partition/PartitionReport.h"
#include "project/ModelBuilder.h"
#include "project/RunProject.h"

namespace test_solver_choice {

using namespace rollsim;

namespace {
Project sample(const std::string& name) {
  return load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / (name + ".json"));
}

double cost_of(const AutoChoice& c, const std::string& mode) {
  for (const ModeCost& m : c.costs)
    if (m.mode == mode) return m.flops;
  return -1;
}

/// The chosen mode is a candidate, has the least cost, and every cost is positive.
void expect_cheapest(const AutoChoice& c) {
  ASSERT_FALSE(c.costs.empty());
  for (const ModeCost& m : c.costs) EXPECT_GT(m.flops, 0) << m.mode;
  const double least = std::min_element(c.costs.begin(), c.costs.end(), [](const ModeCost& a, const ModeCost& b) {
                         return a.flops < b.flops;
                       })->flops;
  EXPECT_EQ(cost_of(c, c.mode), least) << c.reason;
  EXPECT_NE(c.reason.find(c.mode), std::string::npos) << c.reason;
}
}  // namespace

TEST(SolverChoice, OneUndividedBodyWithoutContactIsDirect) {
  const Project p = sample("cantilever-2d-240x60");
  const Model m = build_model(p);
  const AutoChoice c = choose_solver_mode(p.config(), m);
  expect_cheapest(c);
  EXPECT_EQ(c.mode, "direct");
  ASSERT_EQ(c.costs.size(), 2u) << "feti is weighed only with a partitioned body";
  EXPECT_EQ(cost_of(c, "direct"), cost_of(c, "mixed")) << "one body, no interface: the same factor";
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  EXPECT_EQ(cost_of(c, "direct"), predicted_cost(estimate_factor(m.bodies[0].mesh, dofs), {0, 1, 0}));
}

TEST(SolverChoice, ContactMakesTheBorderedLuDearerThanTheInterfaceCg) {
  const Project p = sample("block-indent-2d-90x70");
  const AutoChoice c = choose_solver_mode(p.config(), build_model(p));
  expect_cheapest(c);
  EXPECT_EQ(c.mode, "mixed");
  EXPECT_GT(cost_of(c, "direct"), cost_of(c, "mixed"));
}

TEST(SolverChoice, FetiIsWeighedWithThePartitionTablesCost) {
  Project p = sample("block-indent-dd-2d-50x30");
  const Model m = build_model(p);
  const AutoChoice c = choose_solver_mode(p.config(), m);
  expect_cheapest(c);
  ASSERT_EQ(c.costs.size(), 3u);
  // the partitioned body as the window's table prices it (twice: its AMD estimate flatters a partition), the other
  // body as under mixed
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  ReporterOptions options;  // the sample's preconditioner is dirichlet: the table's default model
  PartitionReporter reporter(m.bodies[0], dofs, options);
  const double table = reporter.update(m.bodies[0].partition).cost;
  const DofMap other(m.bodies[1], 1, m.displacements);
  const double rest = predicted_cost(estimate_factor(m.bodies[1].mesh, other), {25, 1, 1});
  EXPECT_DOUBLE_EQ(cost_of(c, "feti"), 2 * table + rest) << "the partitioned body at twice the table's estimate";
}

TEST(SolverChoice, RunProjectResolvesAutoAndRunsTheChosenMode) {
  Project p = sample("block-indent-2d-50x30");
  p.data["solver"]["mode"] = "auto";
  const Model m = build_model(p);
  const Results r = run_project(p, m);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.auto_choice.has_value());
  expect_cheapest(*r.auto_choice);
  Project chosen = p;
  chosen.data["solver"]["mode"] = r.auto_choice->mode;
  const Results same = run_project(chosen, m);
  EXPECT_FALSE(same.auto_choice.has_value());
  for (size_t b = 0; b < r.bodies.size(); ++b) EXPECT_EQ(r.bodies[b].displacement, same.bodies[b].displacement);
}

TEST(SolverChoice, AutoIsAValidModeAndOtherWordsAreNot) {
  std::ifstream file(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / "block-indent-2d-50x30.json");
  json j = json::parse(file);  // as written (a loaded project carries its defaults, which are not all valid input)
  j["solver"]["mode"] = "auto";
  try {
    parse_project(j.dump(), "p.json");
  } catch (const ProjectError& e) {
    ADD_FAILURE() << "solver.mode 'auto' must be accepted: " << e.what();
  }
  for (const char* bad : {"Auto", "automatic", ""}) {
    j["solver"]["mode"] = bad;
    try {
      parse_project(j.dump(), "p.json");
      ADD_FAILURE() << "solver.mode '" << bad << "' must be refused";
    } catch (const ProjectError& e) {
      EXPECT_NE(std::string(e.what()).find("solver.mode"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(make_solver("auto", {}), std::invalid_argument) << "auto names no strategy of its own";
}

}  // namespace test_solver_choice
