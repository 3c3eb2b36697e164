// The friction direction's stiffness against central differences of the slipping points' friction loads: a block
// on a base, every point slipping under Coulomb friction (μ 0.3) with its own normal force, both bodies moved at
// random over the step so that each point slips its own way; the direction of the trial force d = (δ d₀ − v_t) /
// |δ d₀ − v_t| (−v_t/|v_t| where d₀ is zero) is set by update_friction at each perturbed configuration, as Newton sets
// it. In 3D d turns with the slip, and the term is the exact
// derivative −∂(friction loads)/∂u; in 2D d = ±t cannot turn and there is nothing to add.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

#include "../../common/SlippingBlock.h"
#include "contact/Friction.h"
#include "contact/FrictionStiffness.h"

namespace test_friction_stiffness {

using namespace rollsim;
using testing_support::Slipping;
using testing_support::slipping;

namespace {
using Dof = std::tuple<int, int, int>;  // body, node, component
using Matrix = std::map<std::pair<Dof, Dof>, double>;

/// The pairs after Newton's stick/slip update at u: each point's direction that of its trial force.
std::vector<PairState> updated(const Slipping& s, const std::vector<Eigen::VectorXd>& u) {
  std::vector<PairState> pairs = s.pairs;
  EXPECT_EQ(update_friction(s.model, s.rows, s.lambda, u, s.start, pairs), 0);  // every point keeps slipping
  return pairs;
}

/// −∂(friction loads)/∂u by central differences over the dofs of the contact's nodes.
Matrix differences(const Slipping& s) {
  std::vector<Dof> dofs;
  const PairState& p = s.pairs[0];
  const int dim = s.model.dim, slave = s.model.contacts[0].slave_body, master = s.model.contacts[0].master_body;
  for (const ContactPoint& c : p.points)
    for (int k = 0; k < dim; ++k) {
      dofs.push_back({slave, c.slave_node, k});
      for (int n : c.master_nodes) dofs.push_back({master, n, k});
    }
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  const double h = 1e-7;
  Matrix out;
  for (const Dof& col : dofs) {
    auto [b, n, k] = col;
    std::vector<Eigen::VectorXd> up = s.u, down = s.u;
    up[b][dim * n + k] += h, down[b][dim * n + k] -= h;
    const auto fp = friction_loads(s.model, updated(s, up)), fm = friction_loads(s.model, updated(s, down));
    for (const Dof& row : dofs) {
      auto [bi, ni, ki] = row;
      const double v = -(fp[bi][dim * ni + ki] - fm[bi][dim * ni + ki]) / (2 * h);
      if (v != 0.0) out[{row, col}] = v;
    }
  }
  return out;
}

Matrix summed(const std::vector<StiffnessEntry>& k) {
  Matrix m;
  for (const StiffnessEntry& e : k) m[{{e.body_i, e.node_i, e.comp_i}, {e.body_j, e.node_j, e.comp_j}}] += e.value;
  return m;
}

double largest(const Matrix& m) {
  double x = 0;
  for (const auto& [key, v] : m) x = std::max(x, std::abs(v));
  return x;
}
}  // namespace

/// The term of every slipping point against the differences of the friction loads, entry by entry.
void expect_exact_derivative(const Slipping& s) {
  const Matrix fd = differences(s);
  const Matrix k = summed(slip_direction_stiffness(s.model, updated(s, s.u)));
  // μ N / |v_t| with |v_t| ~ 0.01: the direction turns, and without the term the tangent misses all of this
  const double scale = largest(fd);
  ASSERT_GT(scale, 1.0);
  for (const auto& [key, v] : fd) {
    const auto it = k.find(key);
    EXPECT_NEAR(it == k.end() ? 0.0 : it->second, v, 1e-6 * scale);
  }
  for (const auto& [key, v] : k) EXPECT_TRUE(fd.count(key) || std::abs(v) < 1e-6 * scale);
}

TEST(FrictionStiffness, In3DItIsTheExactDerivativeOfTheFrictionLoads) {
  const Slipping s = slipping(3);
  ASSERT_EQ(s.pairs[0].points.size(), 9u);
  expect_exact_derivative(s);
}

// With the memory d₀ of each point's trial force (its direction where the step began) of the size of its slip: the
// direction then turns by (I − d dᵀ) / |δ d₀ − v_t|, not by 1 / |v_t|
TEST(FrictionStiffness, In3DWithTheTrialForcesMemoryItIsTheExactDerivativeToo) {
  Slipping s = slipping(3);
  s.model.contacts[0].slip_tolerance = 0.05;  // δ 0.0125–0.025 against slips of up to 0.02
  for (Eigen::Vector3d& d0 : s.pairs[0].start_direction) d0 = Eigen::Vector3d(0.6, 0.8, 0);
  expect_exact_derivative(s);
}

TEST(FrictionStiffness, In3DItIsSymmetricPositiveSemidefiniteAndJoinsSlaveAndMaster) {
  const Slipping s = slipping(3);
  const std::vector<StiffnessEntry> entries = slip_direction_stiffness(s.model, updated(s, s.u));
  std::map<Dof, int> index;
  for (const StiffnessEntry& e : entries) index.emplace(Dof{e.body_i, e.node_i, e.comp_i}, 0);
  int n = 0;
  for (auto& [dof, i] : index) i = n++;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  bool joins = false;
  for (const StiffnessEntry& e : entries) {
    K(index.at({e.body_i, e.node_i, e.comp_i}), index.at({e.body_j, e.node_j, e.comp_j})) += e.value;
    joins = joins || e.body_i != e.body_j;
  }
  ASSERT_GT(n, 0);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues().minCoeff(), -1e-12 * K.norm());
  EXPECT_TRUE(joins);  // the slave–master part: only `contact_tangent: full` can hold it
}

TEST(FrictionStiffness, In2DTheDirectionCannotTurn) {
  const Slipping s = slipping(2);
  ASSERT_EQ(s.pairs[0].points.size(), 3u);
  EXPECT_LT(largest(differences(s)), 1e-6);  // the loads do not move with u: d = ±t
  EXPECT_TRUE(slip_direction_stiffness(s.model, updated(s, s.u)).empty());
}

TEST(FrictionStiffness, ADirectionNotSetFromTheSlipAtThisIterateGivesNone) {
  const Slipping s = slipping(3);
  std::vector<PairState> pairs = updated(s, s.u);
  ASSERT_FALSE(slip_direction_stiffness(s.model, pairs).empty());
  new_step(pairs);  // a step begins: the direction is the last step's, the residual's does not move with u
  EXPECT_TRUE(slip_direction_stiffness(s.model, pairs).empty());
  pairs = updated(s, s.start);  // no slip over the step (|v_t| = 0): the direction stays, no term
  EXPECT_TRUE(slip_direction_stiffness(s.model, pairs).empty());
  pairs = updated(s, s.u);
  std::fill(pairs[0].slip.begin(), pairs[0].slip.end(), 0);  // sticking points: their rows hold them
  EXPECT_TRUE(slip_direction_stiffness(s.model, pairs).empty());
}

}  // namespace test_friction_stiffness
