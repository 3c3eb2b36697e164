// The contact's geometric stiffness against central differences of the contact forces Σ_r λ_r C_r(u) (λ held), the
// rows found again in each perturbed configuration as a pair that slides at every iteration finds them: a slave block
// under a quarter ring (a deformable, curved master), both bodies deformed at random. Sliding points: the term is the
// exact derivative (symmetric). Sticking points hold their master point: the exact derivative is unsymmetric and the
// term is its symmetric part.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

#include "contact/ContactStiffness.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

using namespace rollsim;
using json = nlohmann::json;

namespace {
using Dof = std::tuple<int, int, int>;  // body, node, component

Model ring_over_block(const std::string& kind) {
  const json j = {
      {"name", "ring-over-block"},
      {"dimension", 2},
      {"materials", {{{"name", "m"}, {"E", 1000.0}, {"nu", 0.3}}}},
      {"bodies",
       {{{"name", "block"},
         {"material", "m"},
         {"mesh", {{"type", "block"}, {"nx", 12}, {"ny", 2}, {"lx", 0.6}, {"ly", 0.3}, {"origin", {0.0, -0.3}}}}},
        {{"name", "ring"},
         {"material", "m"},
         {"mesh",
          {{"type", "annulus"},
           {"center", {0.0, 1.0}},
           {"inner_radius", 0.5},
           {"outer_radius", 1.0},
           {"n_radial", 2},
           {"n_around", 12},
           {"start_angle", 270.0},
           {"end_angle", 360.0}}}}}},
      {"contacts",
       {{{"name", "c"},
         {"type", kind},
         {"slave_body", "block"},
         {"slave_surface", "ymax"},
         {"master_body", "ring"},
         {"master_surface", "outer"},
         {"search_distance", 0.3},
         {"sliding", "large_every_iteration"}}}},
      {"boundary_conditions", {{{"type", "displacement"}, {"body", "block"}, {"set", "ymin"}, {"ux", 0.0}}}}};
  return build_model(parse_project(j.dump(), "test.json"));
}

std::vector<Eigen::VectorXd> random_displacements(const Model& model, double size) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> d(-size, size);
  std::vector<Eigen::VectorXd> u;
  for (const Body& b : model.bodies) {
    u.emplace_back(b.mesh.num_nodes() * model.dim);
    for (Eigen::Index i = 0; i < u.back().size(); ++i) u.back()[i] = d(gen);
  }
  return u;
}

/// Σ_r λ_r C_r in body terms, the rows found again at u (the points' states carried from `pairs`).
std::map<Dof, double> contact_forces(const Model& model, std::vector<PairState> pairs,
                                     const std::vector<Eigen::VectorXd>& u, const Eigen::VectorXd& lambda) {
  follow_contacts(model, u, pairs, ContactPair::Sliding::Iteration);
  const std::vector<ConstraintRow> rows = contact_rows(model, pairs);
  EXPECT_EQ(static_cast<Eigen::Index>(rows.size()), lambda.size()) << "the perturbation changed the active rows";
  std::map<Dof, double> f;
  for (size_t r = 0; r < rows.size() && static_cast<Eigen::Index>(r) < lambda.size(); ++r)
    for (const ConstraintTerm& t : rows[r].terms)
      f[{t.body, t.node, t.comp}] += lambda[static_cast<Eigen::Index>(r)] * t.coef;
  return f;
}

struct Fixture {
  Model model;
  std::vector<Eigen::VectorXd> u;
  std::vector<PairState> pairs;
  std::vector<ConstraintRow> rows;
  std::vector<int> kept;
  Eigen::VectorXd lambda;
};

/// Every point found in a deformed configuration, active, the ones projected inside a segment only (a projection
/// clamped to a vertex holds its ξ), with compressive multipliers of different sizes.
Fixture deformed_state(const std::string& kind) {
  Fixture s{ring_over_block(kind), {}, {}, {}, {}, {}};
  s.u = random_displacements(s.model, 0.01);
  s.pairs = search_contacts(s.model);
  follow_contacts(s.model, s.u, s.pairs, ContactPair::Sliding::Iteration);
  PairState& p = s.pairs[0];
  for (size_t j = 0; j < p.points.size(); ++j) {
    p.active[j] = p.points[j].N[1] > 1e-3 && p.points[j].N[1] < 1 - 1e-3;
    p.anchor[j] = relative_position(s.model.contacts[0], p.points[j], s.u, 2);  // sticks where it is
  }
  s.rows = contact_rows(s.model, s.pairs);
  s.lambda.resize(static_cast<Eigen::Index>(s.rows.size()));
  for (Eigen::Index r = 0; r < s.lambda.size(); ++r) s.lambda[r] = -1.0 - 0.1 * static_cast<double>(r % 7);
  for (size_t r = 0; r < s.rows.size(); ++r) s.kept.push_back(static_cast<int>(r));
  return s;
}

/// ∂(Σ λ C)/∂u by central differences, column by column over the dofs the stiffness touches.
std::map<std::pair<Dof, Dof>, double> differences(const Fixture& s, const std::vector<StiffnessEntry>& k) {
  std::map<std::pair<Dof, Dof>, double> d;
  std::vector<Dof> columns;
  for (const StiffnessEntry& e : k) columns.push_back({e.body_j, e.node_j, e.comp_j});
  std::sort(columns.begin(), columns.end());
  columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  const double h = 1e-6;
  for (const Dof& c : columns) {
    auto [b, n, comp] = c;
    std::vector<Eigen::VectorXd> up = s.u, down = s.u;
    up[b][2 * n + comp] += h, down[b][2 * n + comp] -= h;
    const auto fp = contact_forces(s.model, s.pairs, up, s.lambda),
               fm = contact_forces(s.model, s.pairs, down, s.lambda);
    for (const auto& [row, v] : fp) d[{row, c}] += v / (2 * h);
    for (const auto& [row, v] : fm) d[{row, c}] -= v / (2 * h);
  }
  return d;
}

std::map<std::pair<Dof, Dof>, double> summed(const std::vector<StiffnessEntry>& k) {
  std::map<std::pair<Dof, Dof>, double> m;
  for (const StiffnessEntry& e : k) m[{{e.body_i, e.node_i, e.comp_i}, {e.body_j, e.node_j, e.comp_j}}] += e.value;
  return m;
}

double largest(const std::map<std::pair<Dof, Dof>, double>& m) {
  double x = 0;
  for (const auto& [key, v] : m) x = std::max(x, std::abs(v));
  return x;
}
}  // namespace

TEST(ContactStiffness, SlidingPointsGiveTheExactDerivativeOfTheContactForces) {
  const Fixture s = deformed_state("frictionless");
  ASSERT_GE(s.rows.size(), 8u);
  const auto k = summed(contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u));
  const auto fd = differences(s, contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u));
  const double scale = largest(fd);
  ASSERT_GT(scale, 1.0);  // λ/l with l ≈ 0.13
  for (const auto& [key, v] : fd) {
    const auto it = k.find(key);
    EXPECT_NEAR(it == k.end() ? 0.0 : it->second, v, 1e-6 * scale);
  }
  for (const auto& [key, v] : k) EXPECT_TRUE(fd.count(key) || std::abs(v) < 1e-6 * scale);
}

TEST(ContactStiffness, IsSymmetricAndHasNoSlaveSlavePart) {
  const Fixture s = deformed_state("frictionless");
  const auto k = summed(contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u));
  ASSERT_FALSE(k.empty());
  for (const auto& [key, v] : k) {
    EXPECT_NEAR(k.at({key.second, key.first}), v, 1e-12 * largest(k));
    EXPECT_FALSE(std::get<0>(key.first) == 0 && std::get<0>(key.second) == 0 && v != 0) << "slave–slave term";
  }
}

TEST(ContactStiffness, StickingPointsGiveTheSymmetricPartOfTheExactDerivative) {
  const Fixture s = deformed_state("sticking");
  ASSERT_GE(s.rows.size(), 16u);  // a normal and a tangential row per point
  const auto k = summed(contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u));
  const auto fd = differences(s, contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u));
  const double scale = largest(fd);
  ASSERT_GT(scale, 1.0);
  double asymmetry = 0;
  for (const auto& [key, v] : fd) {
    const auto t = fd.find({key.second, key.first});
    const double vt = t == fd.end() ? 0.0 : t->second;
    asymmetry = std::max(asymmetry, std::abs(v - vt));
    const auto it = k.find(key);
    EXPECT_NEAR(it == k.end() ? 0.0 : it->second, 0.5 * (v + vt), 1e-6 * scale);
  }
  EXPECT_GT(asymmetry, 0.1 * scale);  // the exact derivative is not symmetric
}

TEST(ContactStiffness, RowsThatDoNotFollowTheConfigurationGetNone) {
  Fixture s = deformed_state("frictionless");
  s.model.contacts[0].sliding = ContactPair::Sliding::Step;  // rows kept through a step's iterations: C is constant
  EXPECT_TRUE(contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u).empty());
}
