// The update policy decides which groups are re-assembled and refactored; every strategy honours it: solving again
// with no version bumped refactors nothing (direct and skyline included), bumping one group refactors that group
// (mixed / feti) or the one global matrix (direct / skyline), and the answer stays the same.
#include <gtest/gtest.h>

#include "analysis/GroupLayout.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "solve/SolverStrategy.h"
#include "solve/UpdatePolicy.h"

namespace test_update_policy {

using namespace rollsim;

namespace {

Model cantilever_2x2() {
  const json mesh = {{"type", "block"}, {"nx", 12}, {"ny", 6}, {"lx", 12}, {"ly", 6}};
  const json j = {{"name", "policy"},
                  {"dimension", 2},
                  {"materials", {{{"name", "m"}, {"E", 1000.0}, {"nu", 0.3}}}},
                  {"bodies", {{{"name", "beam"}, {"material", "m"}, {"mesh", mesh}, {"partition", "2x2"}}}},
                  {"boundary_conditions",
                   {{{"type", "displacement"}, {"body", "beam"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}},
                    {{"type", "force"}, {"body", "beam"}, {"set", "xmax"}, {"fy", 1.0}}}}};
  return build_model(parse_project(j.dump(), "test"));
}

long total(const SolveStats& s) {
  long n = 0;
  for (const auto& [group, count] : s.factorizations) n += count;
  return n;
}

}  // namespace

TEST(UpdatePolicy, AlwaysSelectsEveryGroupAndMarkingBumpsTheirVersions) {
  BlockSystem sys;
  sys.groups.resize(3);
  const auto policy = make_update_policy("always");
  EXPECT_EQ(policy->name(), "always");
  EXPECT_EQ(policy->select(sys, {}), (std::vector<size_t>{0, 1, 2}));
  mark_updated(sys, {1});
  EXPECT_EQ(sys.groups[0].version, 0);
  EXPECT_EQ(sys.groups[1].version, 1);
  EXPECT_THROW(make_update_policy("sometimes"), std::invalid_argument);
}

TEST(UpdatePolicy, EveryStrategyRefactorsExactlyWhatWasMarked) {
  const Model model = cantilever_2x2();
  for (const std::string mode : {"skyline", "direct", "mixed", "feti"}) {
    SCOPED_TRACE(mode);
    const SolverOptions o{1e-10, 1, Preconditioner::Dirichlet};
    auto solver = make_solver(mode, o);
    GroupLayout layout(model, solver->uses_subdomains(), Multipliers::NonRedundant);
    BlockSystem& sys = layout.system();
    layout.assemble(all_groups(sys), {}, 1.0);
    mark_updated(sys, AlwaysUpdate().select(sys, {}));
    const BlockSolution first = solver->solve(sys);
    const long groups = static_cast<long>(sys.groups.size());
    EXPECT_EQ(total(solver->stats()), groups);  // a global factorization counts once per group it holds
    solver->solve(sys);
    EXPECT_EQ(total(solver->stats()), groups) << "nothing marked: nothing refactored";
    mark_updated(sys, {0});
    const BlockSolution again = solver->solve(sys);
    EXPECT_EQ(total(solver->stats()), mode == "feti" ? groups + 1 : 2 * groups);
    EXPECT_EQ(solver->stats().factorizations.at(sys.groups[0].name), 2);
    for (size_t g = 0; g < sys.groups.size(); ++g)
      EXPECT_LT((again.u[g] - first.u[g]).norm(), 1e-9 * (1 + first.u[g].norm()));
  }
}

}  // namespace test_update_policy
