// The mixed strategy on the floating-body sample (block held only by tied contact): projected CG keeps
// Gᵀλ = e to round-off at every iteration, and a tighter CG tolerance moves the answer towards `direct`.
#include <gtest/gtest.h>

#include <filesystem>

#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "solve/MixedStrategy.h"

namespace test_mixed_floating {

using namespace rollsim;

namespace {
Model sample(const std::string& name) {
  return build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / name));
}
double max_difference(const Results& a, const Results& b) {
  double d = 0;
  for (size_t i = 0; i < a.bodies.size(); ++i)
    d = std::max(d, (a.bodies[i].displacement - b.bodies[i].displacement).cwiseAbs().maxCoeff());
  return d;
}
}  // namespace

TEST(MixedFloating, ProjectedCGHoldsTheSolvabilityConstraint) {
  const Model model = sample("block-push-2d-50x30.json");
  auto direct = make_solver("direct", {});
  const Results ref = run_linear_static(model, *direct);
  ASSERT_EQ(ref.rigid_modes, 3);
  double previous = 1e300;
  for (const double tol : {1e-3, 1e-5, 1e-7, 1e-9}) {
    MixedStrategy mixed({tol, 1});
    const Results res = run_linear_static(model, mixed);
    const ProjectedCGResult& cg = mixed.last_interface_solve();
    EXPECT_TRUE(cg.converged);
    EXPECT_LT(cg.max_constraint_error, 1e-12) << "G^T lambda = e at every iteration, tol " << tol;
    EXPECT_EQ(cg.alpha.size(), 3);
    const double diff = max_difference(res, ref) / ref.bodies[1].displacement.cwiseAbs().maxCoeff();
    EXPECT_LE(diff, previous) << "tol " << tol;
    previous = diff;
  }
  EXPECT_LT(previous, 1e-8);
  EXPECT_NEAR(ref.contacts.at(0).normal_force, 8.4, 1e-9) << "the contact carries the whole push";
}

TEST(MixedFloating, FactorsEachBodyOnceAcrossActiveSetIterations) {
  const Model model = sample("cylinder-indent-2d.json");
  MixedStrategy mixed({1e-8, 1});
  const Results res = run_linear_static(model, mixed);
  EXPECT_EQ(to_string(res.status.status), std::string("converged"));
  EXPECT_GT(res.active_set_iterations, 1);
  for (const auto& [group, count] : mixed.stats().factorizations) EXPECT_EQ(count, 1) << group;
}

}  // namespace test_mixed_floating
