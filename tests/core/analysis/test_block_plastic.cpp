// Paper Example 5 reduced (sample block-plastic-3d with its base at 12 × 6 × 4 and its block at 2 × 2 × 1): an
// elastic block pushed into an elastoplastic base by its own height at finite strain gives the same contact force
// with `direct` refactoring at every iteration and with FETI on a partitioned base under the selective update
// (DD-II), and DD-II refactors the base's subdomains fewer times than Newton iterates.
#include <gtest/gtest.h>

#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_block_plastic {

using namespace rollsim;

namespace {
Results run_with(const std::string& mode, const std::string& update, const std::string& partition = "") {
  Project p = load_project(std::string(ROLLSIM_SOURCE_DIR) + "/samples/block-plastic-3d.json");
  p.data["bodies"][0]["mesh"].update({{"nx", 12}, {"ny", 6}, {"nz", 4}});
  p.data["bodies"][1]["mesh"].update({{"nx", 2}, {"ny", 2}, {"nz", 1}});
  p.data["solver"]["mode"] = mode;
  p.data["solver"]["update"] = update;
  if (!partition.empty()) p.data["bodies"][0]["partition"] = partition;
  return run_project(p, build_model(p));
}

long base_factorizations(const Results& r) {
  long n = 0;
  for (const auto& [group, count] : r.solver.factorizations)
    if (group.rfind("base", 0) == 0) n += count;
  return n;
}
}  // namespace

TEST(BlockPlastic, DirectAndDdTwoAgreeAndDdTwoKeepsFactors) {
  const Results direct = run_with("direct", "always");
  const Results dd2 = run_with("feti", "selective", "1x2x1");
  ASSERT_EQ(direct.status.status, Status::converged) << direct.status.message;
  ASSERT_EQ(dd2.status.status, Status::converged) << dd2.status.message;
  const double force = direct.contacts.at(0).normal_force;
  EXPECT_GT(force, 0.0);
  EXPECT_NEAR(dd2.contacts.at(0).normal_force, force, 2e-3 * force) << "the same answer";
  const long iterations = static_cast<long>(dd2.newton.size()), subdomains = 2;
  EXPECT_LT(base_factorizations(dd2), subdomains * iterations) << "DD-II keeps some subdomain's factor";
}

// The base torn across its height (1x1x2) leaves its top layer floating. Stressed, that subdomain's tangent has only
// the translations as kernel; with its rotations taken as kernel too, each FETI solve inverted a different tangent
// and Newton converged linearly (twice `direct`'s iterations on the full Example 5). Now the same iterations.
TEST(BlockPlastic, AFloatingSubdomainTakesDirectsNewtonIterations) {
  const Results direct = run_with("direct", "always");
  const Results dd1 = run_with("feti", "always", "1x1x2");
  ASSERT_EQ(direct.status.status, Status::converged) << direct.status.message;
  ASSERT_EQ(dd1.status.status, Status::converged) << dd1.status.message;
  const double force = direct.contacts.at(0).normal_force;
  EXPECT_NEAR(dd1.contacts.at(0).normal_force, force, 1e-6 * force);
  const long increments = static_cast<long>(direct.increments.size());
  EXPECT_LE(std::labs(static_cast<long>(dd1.newton.size()) - static_cast<long>(direct.newton.size())), increments)
      << "direct " << direct.newton.size() << ", feti 1x1x2 " << dd1.newton.size() << " Newton iterations";
}

}  // namespace test_block_plastic
