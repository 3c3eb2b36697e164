// The frictionless active-set decision trusts a multiplier only to the accuracy it was computed with: a point whose
// λ is tensile by less than `tolerance` × max|λ| (zero to that accuracy, e.g. CG noise) keeps its status, while a
// clearly tensile one leaves. Without the tolerance a λ of +1e-12 released the point and the active set could cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "contact/ContactConstraints.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

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
