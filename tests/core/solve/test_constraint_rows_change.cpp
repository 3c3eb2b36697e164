// Cached factorizations and preconditioners are keyed to the constraint rows themselves, not to their count: an
// active set that swaps rows while keeping their number (points leaving and entering together) must give what a
// fresh solver gives. Before, `direct` kept UMFPACK's symbolic analysis of the old pattern and the FETI
// preconditioner kept its old rows.
#include <gtest/gtest.h>

#include "analysis/GroupLayout.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "solve/MixedStrategy.h"

namespace test_constraint_rows_change {

using namespace rollsim;

namespace {

/// A 2D cantilever (16 × 8 unit elements, clamped at x = 0, tip load) partitioned `partition` ("": whole).
Model cantilever(const std::string& partition) {
  const json mesh = {{"type", "block"}, {"nx", 16}, {"ny", 8}, {"lx", 16}, {"ly", 8}};
  json body = {{"name", "beam"}, {"material", "m"}, {"mesh", mesh}};
  if (!partition.empty()) body["partition"] = partition;
  const json j = {{"name", "rows"},
                  {"dimension", 2},
                  {"materials", {{{"name", "m"}, {"E", 1000.0}, {"nu", 0.3}}}},
                  {"bodies", {body}},
                  {"boundary_conditions",
                   {{{"type", "displacement"}, {"body", "beam"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}},
                    {{"type", "force"}, {"body", "beam"}, {"set", "xmax"}, {"fy", 1.0}}}}};
  return build_model(parse_project(j.dump(), "test"));
}

/// Rows u(dof_k) = 0.01 k: two constraint rows on the given free dofs of body 0 (standing in for contact rows).
BodyConstraints rows_on(const GroupLayout& layout, int first, int second) {
  const int n = layout.body_dofs()[0]->num_free();
  SparseMatrix C(2, n);
  C.insert(0, first) = 1.0;
  C.insert(1, second) = 1.0;
  C.makeCompressed();
  Eigen::VectorXd d(2);
  d << 0.01, 0.02;
  return BodyConstraints{{C}, d, {0, 1}};
}

Eigen::VectorXd stacked(const BlockSolution& s) {
  Eigen::VectorXd all(0);
  for (const auto& u : s.u) {
    Eigen::VectorXd next(all.size() + u.size());
    next << all, u;
    all = next;
  }
  Eigen::VectorXd out(all.size() + s.lambda.size());
  out << all, s.lambda;
  return out;
}

/// Solves with rows on dofs (a, b), then (c, d) with the same strategy, and (c, d) with a fresh one.
template <class Make>
void expect_swap_equals_fresh(const Model& model, bool split, Make make) {
  GroupLayout layout(model, split, Multipliers::NonRedundant);
  layout.assemble(all_groups(layout.system()), {}, 1.0);
  const int n = layout.body_dofs()[0]->num_free();
  auto reused = make();
  layout.set_contact(rows_on(layout, n / 3, n / 2));
  reused->solve(layout.system());
  layout.set_contact(rows_on(layout, n / 4, 2 * n / 3));  // same count, other rows
  const BlockSolution again = reused->solve(layout.system());
  auto fresh = make();
  const BlockSolution first = fresh->solve(layout.system());
  ASSERT_TRUE(again.status.ok()) << again.status.message;
  EXPECT_LT((stacked(again) - stacked(first)).norm() / stacked(first).norm(), 1e-9);
}

}  // namespace

TEST(ConstraintRowsChange, DirectReanalysesASwapOfEqualCount) {
  const Model model = cantilever("");
  for (const std::string mode : {"direct", "skyline"}) {
    SCOPED_TRACE(mode);
    expect_swap_equals_fresh(model, false, [&] { return make_solver(mode, {}); });
  }
}

TEST(ConstraintRowsChange, FetiPreconditionerFollowsTheRowsNotTheirCount) {
  const Model model = cantilever("2x2");
  for (const std::string pc : {"lumped", "dirichlet"}) {
    SCOPED_TRACE(pc);
    const SolverOptions o{1e-10, 1, from_word<Preconditioner>(pc)};
    GroupLayout layout(model, true, Multipliers::NonRedundant);
    layout.assemble(all_groups(layout.system()), {}, 1.0);
    const int n = layout.body_dofs()[0]->num_free();
    MixedStrategy reused(o, true);
    layout.set_contact(rows_on(layout, n / 3, n / 2));
    reused.solve(layout.system());
    layout.set_contact(rows_on(layout, n / 4, 2 * n / 3));
    const long before = reused.stats().cg_iterations;
    const BlockSolution again = reused.solve(layout.system());
    MixedStrategy fresh(o, true);
    const BlockSolution first = fresh.solve(layout.system());
    ASSERT_TRUE(again.status.ok()) << again.status.message;
    EXPECT_EQ(reused.stats().cg_iterations - before, fresh.stats().cg_iterations) << "a stale preconditioner";
    EXPECT_LT((stacked(again) - stacked(first)).norm() / stacked(first).norm(), 1e-9);
  }
}

}  // namespace test_constraint_rows_change
