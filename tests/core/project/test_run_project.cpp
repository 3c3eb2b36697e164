// The one run entry point: run_project gives what the linear driver gives with the project's solver (bit for bit),
// carries the solver's statistics in Results, and the analysis is chosen by name (analysis.type) from a registry
// whose names the schema validates.
#include <gtest/gtest.h>

#include <filesystem>

#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "project/RunProject.h"

namespace test_run_project {

using namespace rollsim;

namespace {
Project sample(const std::string& name) {
  return load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / (name + ".json"));
}
}  // namespace

TEST(RunProject, EqualsTheLinearDriverWithTheProjectsSolver) {
  const Project p = sample("cylinder-indent-2d");
  const Model model = build_model(p);
  const Results r = run_project(p, model);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  auto solver = make_solver(p.config().solver_mode, p.config().solver);
  const Results direct = run_linear_static(model, *solver);
  ASSERT_EQ(r.bodies.size(), direct.bodies.size());
  for (size_t b = 0; b < r.bodies.size(); ++b) EXPECT_EQ(r.bodies[b].displacement, direct.bodies[b].displacement);
  EXPECT_EQ(r.solver.solves, solver->stats().solves);
  EXPECT_EQ(r.solver.factorizations, solver->stats().factorizations);
  EXPECT_GT(r.solver.solves, 1) << "frictionless contact: several active-set solves";
}

TEST(RunProject, AnalysisIsChosenByNameAndValidated) {
  EXPECT_EQ(analysis_names(), (std::vector<std::string>{"linear", "newton"}));
  json j = sample("cantilever-2d-240x60").data;
  j["analysis"] = {{"type", "arc_length"}};
  try {
    parse_project(j.dump(), "p.json");
    FAIL() << "an unknown analysis type must be refused";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("analysis.type"), std::string::npos) << e.what();
  }
}

}  // namespace test_run_project
