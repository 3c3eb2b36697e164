// The frictionless active-set decision trusts a multiplier only to the accuracy it was computed with: a point whose
// λ is tensile by less than `tolerance` × max|λ| (zero to that accuracy, e.g. CG noise) keeps its status, while a
// clearly tensile one leaves. Without the tolerance a λ of +1e-12 released the point and the active set could cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "contact/ContactConstraints.h"
#include "contact/Friction.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_active_set_tolerance {

using namespace rollsim;

namespace {
struct Indent {
  Model model =
      build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / "cylinder-indent-2d.json"));
  std::vector<PairState> pairs = all_active(search_contacts(model));
  std::vector<ConstraintRow> rows = contact_rows(model, pairs);
  static std::vector<PairState> all_active(std::vector<PairState> pairs) {  // every candidate point holds a row
    for (PairState& p : pairs) std::fill(p.active.begin(), p.active.end(), 1);
    return pairs;
  }
  std::vector<Eigen::VectorXd> zero_u() const {
    std::vector<Eigen::VectorXd> u;
    for (const Body& b : model.bodies) u.push_back(Eigen::VectorXd::Zero(b.mesh.num_nodes() * model.dim));
    return u;
  }
};

int active(const std::vector<PairState>& pairs) {
  int n = 0;
  for (const PairState& p : pairs)
    for (char a : p.active) n += a;
  return n;
}
}  // namespace

TEST(ActiveSetTolerance, MultiplierZeroToItsAccuracyKeepsThePoint) {
  Indent c;
  ASSERT_GT(c.rows.size(), 2u);
  const int before = active(c.pairs);
  Eigen::VectorXd lambda = -Eigen::VectorXd::Ones(static_cast<Eigen::Index>(c.rows.size()));  // compressive
  lambda[0] = 1e-12;                                                                          // noise at zero
  auto pairs = c.pairs;
  EXPECT_EQ(update_active_set(c.model, c.rows, lambda, c.zero_u(), pairs, 1e-10), 0);
  EXPECT_EQ(active(pairs), before);
  pairs = c.pairs;
  EXPECT_EQ(update_active_set(c.model, c.rows, lambda, c.zero_u(), pairs, 0.0), 1) << "no tolerance: it leaves";
}

TEST(ActiveSetTolerance, ClearlyTensileMultiplierLeaves) {
  Indent c;
  Eigen::VectorXd lambda = -Eigen::VectorXd::Ones(static_cast<Eigen::Index>(c.rows.size()));
  lambda[1] = 1e-3;  // tensile beyond a CG tolerance of 1e-4
  auto pairs = c.pairs;
  EXPECT_EQ(update_active_set(c.model, c.rows, lambda, c.zero_u(), pairs, 1e-4), 1);
  EXPECT_EQ(active(pairs), active(c.pairs) - 1);
}

// A point that chatters within a step (pulled off, then pressed in again) stays in contact for the rest of the step,
// even when its multiplier is tensile again: without the rule a node at the exit of a rolling pass went in and out
// at every iteration. The next step lets it leave.
TEST(ActiveSetTolerance, PointThatCameBackInStaysForTheStep) {
  Indent c;
  Eigen::VectorXd lambda = -Eigen::VectorXd::Ones(static_cast<Eigen::Index>(c.rows.size()));
  lambda[0] = 1.0;  // clearly tensile: the first row's point leaves
  auto pairs = c.pairs;
  const ConstraintRow& row = c.rows[0];
  ASSERT_EQ(update_active_set(c.model, c.rows, lambda, c.zero_u(), pairs, 1e-8), 1);
  ASSERT_FALSE(pairs[row.pair].active[row.point]);
  std::vector<Eigen::VectorXd> u = c.zero_u();  // pressed in again: its slave node moved 1e-3 into the master
  const ContactPoint& p = pairs[row.pair].points[row.point];
  for (int k = 0; k < c.model.dim; ++k)
    u[c.model.contacts[row.pair].slave_body][p.slave_node * c.model.dim + k] -= 1e-3 * p.normal[k];
  ASSERT_EQ(update_active_set(c.model, {}, Eigen::VectorXd(), u, pairs, 1e-8), 1);
  ASSERT_TRUE(pairs[row.pair].active[row.point]);
  auto held = pairs;  // tensile again: it stays for this step
  EXPECT_EQ(update_active_set(c.model, c.rows, lambda, u, held, 1e-8), 0);
  EXPECT_TRUE(held[row.pair].active[row.point]);
  new_step(pairs);  // a new step: it may leave
  EXPECT_EQ(update_active_set(c.model, c.rows, lambda, u, pairs, 1e-8), 1);
  EXPECT_FALSE(pairs[row.pair].active[row.point]);
}

}  // namespace test_active_set_tolerance
