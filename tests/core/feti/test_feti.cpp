// FETI (`feti` strategy over subdomain groups): the same displacements as `direct` for every preconditioner,
// multiplier choice and projector, in 2D and 3D, with structured and METIS partitions and with contact; Gᵀλ = e held; a
// painted (explicit) map gives what the structured spelling gives; threads change nothing, bit for bit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "solve/MixedStrategy.h"

namespace test_feti {

using namespace rollsim;

namespace {
/// A cantilever clamped at x = 0 with a tip force, 2D nx × ny or 3D nx × ny × nz unit elements.
json cantilever(int dim, int nx, int ny, int nz, const std::string& partition) {
  json mesh = {{"type", "block"}, {"nx", nx}, {"ny", ny}, {"lx", nx}, {"ly", ny}};
  json fixed = {{"type", "displacement"}, {"body", "beam"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}};
  if (dim == 3) {
    mesh["nz"] = nz, mesh["lz"] = nz;
    fixed["uz"] = 0.0;
  }
  return {{"name", "feti-test"},
          {"dimension", dim},
          {"materials", {{{"name", "m"}, {"E", 1000.0}, {"nu", 0.3}}}},
          {"bodies", {{{"name", "beam"}, {"material", "m"}, {"mesh", mesh}, {"partition", partition}}}},
          {"boundary_conditions",
           {fixed, {{"type", "force"}, {"body", "beam"}, {"set", "xmax"}, {"fy", dim == 2 ? 1.0 : 0.2}}}}};
}

Results solve(const Model& model, const std::string& mode, SolverOptions o = {1e-10, 1}) {
  auto solver = make_solver(mode, o);
  return run_linear_static(model, *solver);
}

double relative_difference(const Results& a, const Results& b) {
  double d = 0, u = 0;
  for (size_t i = 0; i < a.bodies.size(); ++i) {
    d = std::max(d, (a.bodies[i].displacement - b.bodies[i].displacement).cwiseAbs().maxCoeff());
    u = std::max(u, b.bodies[i].displacement.cwiseAbs().maxCoeff());
  }
  return d / u;
}

void expect_feti_equals_direct(const Model& model, const std::string& what) {
  const Results direct = solve(model, "direct");
  for (const std::string pc : {"none", "lumped", "dirichlet"})
    for (const std::string glue : {"nonredundant", "redundant"})
      for (const std::string projector : {"preconditioner", "identity"}) {
        if (pc == "none" && projector == "identity") continue;  // without a preconditioner Q = I anyway
        const std::string variant = what + " " + pc + " " + glue + " " + projector;
        SolverOptions o{1e-10, 1, from_word<Preconditioner>(pc), from_word<GlueMultipliers>(glue),
                        from_word<ProjectorMetric>(projector)};
        MixedStrategy feti(o, true);
        const Results r = run_linear_static(model, feti);
        EXPECT_GT(r.subdomains, 1) << what;
        EXPECT_LT(relative_difference(r, direct), 1e-7) << variant;
        EXPECT_TRUE(feti.last_interface_solve().converged) << variant;
        EXPECT_LT(feti.last_interface_solve().max_constraint_error, 1e-10) << variant;
        if (pc == "dirichlet" && model.contacts.empty())  // FETI theory: the Dirichlet-preconditioned operator
          EXPECT_GE(feti.last_interface_solve().lambda_min, 1.0 - 1e-6) << variant << ": λ_min ≥ 1";
      }
}

Model model_of(const json& j) { return build_model(parse_project(j.dump(), "test")); }
}  // namespace

TEST(Feti, EqualsDirect2DStructuredAndMetis) {
  expect_feti_equals_direct(model_of(cantilever(2, 24, 12, 0, "3x2")), "2D 3x2");
  expect_feti_equals_direct(model_of(cantilever(2, 24, 12, 0, "metis:5")), "2D metis:5");
}

TEST(Feti, EqualsDirect3D) { expect_feti_equals_direct(model_of(cantilever(3, 8, 6, 6, "2x2x2")), "3D 2x2x2"); }

TEST(Feti, EqualsDirectWithContact) {
  std::ifstream in(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / "block-indent-dd-2d-50x30.json");
  const Model model = model_of(json::parse(in));
  expect_feti_equals_direct(model, "contact + DD");
}

TEST(Feti, PaintedMapEqualsStructuredPartition) {
  const json structured = cantilever(2, 24, 12, 0, "4x3");
  const Model a = model_of(structured);
  json painted = structured;
  painted["bodies"][0].erase("partition");
  painted["bodies"][0]["partition_map"] = a.bodies[0].partition.element_subdomain;
  const Model b = model_of(painted);
  EXPECT_EQ(a.bodies[0].partition.element_subdomain, b.bodies[0].partition.element_subdomain);
  SolverOptions o{1e-8, 1, Preconditioner::Dirichlet, GlueMultipliers::NonRedundant};
  const Results ra = solve(a, "feti", o), rb = solve(b, "feti", o);
  EXPECT_EQ(ra.interface_multipliers, rb.interface_multipliers);
  EXPECT_EQ(ra.rigid_modes, rb.rigid_modes);
  EXPECT_EQ(relative_difference(ra, rb), 0.0) << "the same groups in the same order: the same arithmetic";
}

TEST(Feti, ThreadsGiveBitIdenticalResults) {
  const Model model = model_of(cantilever(2, 24, 12, 0, "4x2"));
  const Results one = solve(model, "feti", {1e-8, 1, Preconditioner::Dirichlet, GlueMultipliers::NonRedundant});
  const Results two = solve(model, "feti", {1e-8, 2, Preconditioner::Dirichlet, GlueMultipliers::NonRedundant});
  EXPECT_EQ(relative_difference(one, two), 0.0);
}

TEST(Feti, ThreadsGiveBitIdenticalResultsWhereCholmodOrdersWithMetis) {
  // 12³-element subdomains: CHOLMOD tries METIS after AMD, and METIS's process-wide random state once made two
  // concurrent orderings differ from run to run (~1e-7 in u); the pool's dynamic scheduling must not bring it back
  const Model model = model_of(cantilever(3, 24, 24, 24, "2x2x2"));
  const Results one = solve(model, "feti", {1e-6, 1, Preconditioner::Dirichlet, GlueMultipliers::NonRedundant});
  const Results two = solve(model, "feti", {1e-6, 2, Preconditioner::Dirichlet, GlueMultipliers::NonRedundant});
  const Results again = solve(model, "feti", {1e-6, 2, Preconditioner::Dirichlet, GlueMultipliers::NonRedundant});
  EXPECT_EQ(relative_difference(one, two), 0.0);
  EXPECT_EQ(relative_difference(two, again), 0.0);
}

}  // namespace test_feti
