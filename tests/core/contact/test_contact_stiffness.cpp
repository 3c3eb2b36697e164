// The contact's geometric stiffness against central differences of the contact forces Σ_r λ_r C_r(u) (λ held), the
// rows found again in each perturbed configuration as a pair that slides at every iteration finds them: a slave block
// under a quarter ring (2D) or a quarter cylinder (3D, its bilinear faces), a deformable, curved master, both bodies
// deformed at random (in 3D the master's faces then warp: x_,ξη has a normal part), or the master left undeformed
// (flat faces). Sliding points: the term is the exact derivative (symmetric). Sticking points hold their master
// point: the exact derivative is unsymmetric and the term is its symmetric part.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

#include "contact/ContactStiffness.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_contact_stiffness {

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

json contact(const std::string& kind) {
  return {{"name", "c"},
          {"type", kind},
          {"slave_body", "block"},
          {"slave_surface", "zmax"},
          {"master_body", "cylinder"},
          {"master_surface", "outer"},
          {"search_distance", 0.3},
          {"sliding", "large_every_iteration"}};
}

/// A 0.6 × 0.3 × 0.3 block under a quarter cylinder (axis along y, 12 faces around, 2 along the axis).
Model cylinder_over_block(const std::string& kind) {
  const json j = {{"name", "cylinder-over-block"},
                  {"dimension", 3},
                  {"materials", {{{"name", "m"}, {"E", 1000.0}, {"nu", 0.3}}}},
                  {"bodies",
                   {{{"name", "block"},
                     {"material", "m"},
                     {"mesh",
                      {{"type", "block"},
                       {"nx", 6},
                       {"ny", 3},
                       {"nz", 1},
                       {"lx", 0.6},
                       {"ly", 0.3},
                       {"lz", 0.3},
                       {"origin", {0.02, 0.05, -0.3}}}}},
                    {{"name", "cylinder"},
                     {"material", "m"},
                     {"mesh",
                      {{"type", "cylinder"},
                       {"center", {0.0, 1.0}},
                       {"y0", 0.0},
                       {"length", 0.4},
                       {"inner_radius", 0.5},
                       {"outer_radius", 1.0},
                       {"n_radial", 1},
                       {"n_around", 12},
                       {"n_axial", 2},
                       {"start_angle", 270.0},
                       {"end_angle", 360.0}}}}}},
                  {"contacts", {contact(kind)}},
                  {"boundary_conditions",
                   {{{"type", "displacement"}, {"body", "block"}, {"set", "zmin"}, {"ux", 0.0}, {"uy", 0.0}}}}};
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

/// Whether a point's projection lies inside its facet by a margin (a perturbation keeps it on the facet, and a
/// projection clamped to the border holds its ξ): every shape function value away from 0 (segment) or ξ, η away from
/// ±1 (face).
bool well_inside(const ContactPoint& c) {
  if (c.N.size() == 2) return c.N[1] > 1e-3 && c.N[1] < 1 - 1e-3;
  const double xi = c.N[1] + c.N[2] - c.N[0] - c.N[3], eta = c.N[2] + c.N[3] - c.N[0] - c.N[1];
  return std::abs(xi) < 1 - 1e-3 && std::abs(eta) < 1 - 1e-3;
}

enum class Master { Deformed, Undeformed };

/// Every point found in a deformed configuration, active, the ones projected well inside a facet only, with
/// compressive multipliers of different sizes; the master deformed at random too, or not (3D: flat faces).
Fixture deformed_state(int dim, const std::string& kind, Master master = Master::Deformed) {
  Fixture s{dim == 2 ? ring_over_block(kind) : cylinder_over_block(kind), {}, {}, {}, {}, {}};
  s.u = random_displacements(s.model, 0.01);
  if (master == Master::Undeformed) s.u[1].setZero();
  s.pairs = search_contacts(s.model);
  follow_contacts(s.model, s.u, s.pairs, ContactPair::Sliding::Iteration);
  PairState& p = s.pairs[0];
  for (size_t j = 0; j < p.points.size(); ++j) {
    p.active[j] = well_inside(p.points[j]);
    p.anchor[j] = relative_position(s.model.contacts[0], p.points[j], s.u, dim);  // sticks where it is
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
  const int dim = s.model.dim;
  for (const Dof& c : columns) {
    auto [b, n, comp] = c;
    std::vector<Eigen::VectorXd> up = s.u, down = s.u;
    up[b][dim * n + comp] += h, down[b][dim * n + comp] -= h;
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

/// The term equals the central differences (to 1e-6 of their largest entry): the exact derivative.
void expect_exact(const Fixture& s) {
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

/// The largest |n · x_,ξη| / |x_,ξ| over the faces holding the active points (0 for a flat face).
double warp(const Fixture& s) {
  double w = 0;
  const PairState& p = s.pairs[0];
  for (size_t j = 0; j < p.points.size(); ++j) {
    if (!p.active[j]) continue;
    Eigen::Vector3d x[4];
    for (int k = 0; k < 4; ++k) {
      const int n = p.points[j].master_nodes[k];
      const auto& X = s.model.bodies[1].mesh.nodes[n];
      x[k] = Eigen::Vector3d(X[0], X[1], X[2]) + s.u[1].segment<3>(3 * n);
    }
    const Eigen::Vector3d twist = 0.25 * (x[0] - x[1] + x[2] - x[3]), side = 0.5 * (x[1] - x[0] + x[2] - x[3]);
    w = std::max(w, std::abs(p.points[j].normal.dot(twist)) / side.norm());
  }
  return w;
}
}  // namespace

TEST(ContactStiffness, SlidingPointsGiveTheExactDerivativeOfTheContactForces) {
  const Fixture s = deformed_state(2, "frictionless");
  ASSERT_GE(s.rows.size(), 8u);
  expect_exact(s);
}

TEST(ContactStiffness, SlidingPointsOnWarpedFacesGiveTheExactDerivative) {
  const Fixture s = deformed_state(3, "frictionless");
  ASSERT_GE(s.rows.size(), 10u);
  ASSERT_GT(warp(s), 1e-3);  // the curvature term h_12 = n · x_,ξη is there
  expect_exact(s);
}

TEST(ContactStiffness, SlidingPointsOnFlatFacesGiveTheExactDerivative) {
  const Fixture s = deformed_state(3, "frictionless", Master::Undeformed);
  ASSERT_GE(s.rows.size(), 10u);
  ASSERT_LT(warp(s), 1e-12);
  expect_exact(s);
}

class ContactStiffnessDim : public ::testing::TestWithParam<int> {};

/// Slave–slave entries: the gap's Hessian has them only through the face's curvature h_12 (a warped face).
double slave_slave(const std::map<std::pair<Dof, Dof>, double>& k) {
  double x = 0;
  for (const auto& [key, v] : k)
    if (std::get<0>(key.first) == 0 && std::get<0>(key.second) == 0) x = std::max(x, std::abs(v));
  return x;
}

TEST_P(ContactStiffnessDim, IsSymmetricAndHasNoSlaveSlavePartOnFlatFacets) {
  const Fixture s = deformed_state(GetParam(), "frictionless", GetParam() == 2 ? Master::Deformed : Master::Undeformed);
  const auto k = summed(contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u));
  ASSERT_FALSE(k.empty());
  for (const auto& [key, v] : k) EXPECT_NEAR(k.at({key.second, key.first}), v, 1e-12 * largest(k));
  EXPECT_EQ(slave_slave(k), 0.0);
}

TEST(ContactStiffness, WarpedFacesHaveASymmetricSlaveSlavePart) {
  const Fixture s = deformed_state(3, "frictionless");
  const auto k = summed(contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u));
  ASSERT_FALSE(k.empty());
  for (const auto& [key, v] : k) EXPECT_NEAR(k.at({key.second, key.first}), v, 1e-12 * largest(k));
  EXPECT_GT(slave_slave(k), 1e-6 * largest(k));  // the normal turns as the slave moves over the face
}

TEST_P(ContactStiffnessDim, StickingPointsGiveTheSymmetricPartOfTheExactDerivative) {
  const Fixture s = deformed_state(GetParam(), "sticking");
  ASSERT_GE(s.rows.size(), GetParam() == 2 ? 16u : 30u);  // a normal and dim − 1 tangential rows per point
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

TEST_P(ContactStiffnessDim, RowsThatDoNotFollowTheConfigurationGetNone) {
  Fixture s = deformed_state(GetParam(), "frictionless");
  s.model.contacts[0].sliding = ContactPair::Sliding::Step;  // rows kept through a step's iterations: C is constant
  EXPECT_TRUE(contact_geometric_stiffness(s.model, s.pairs, s.rows, s.kept, s.lambda, s.u).empty());
}

INSTANTIATE_TEST_SUITE_P(Dimensions, ContactStiffnessDim, ::testing::Values(2, 3));

namespace {
/// Every body's every dof one after the other (body-major, then node-major): where (body, node, comp) sits.
long dof_index(const Model& model, const Dof& d) {
  long offset = 0;
  for (int b = 0; b < std::get<0>(d); ++b) offset += model.bodies[b].mesh.num_nodes() * model.dim;
  return offset + model.dim * std::get<1>(d) + std::get<2>(d);
}

/// ‖(I − P) K du‖ / (‖K‖ ‖du‖), P the projection onto range(Cᵀ), for a random du with C du = 0 (the rows' motion
/// held, as in every Newton iteration after a step's first): 0 when the term only shifts the multipliers.
double outside_rows(const Fixture& s, const std::vector<StiffnessEntry>& k) {
  long n = 0;
  for (const Body& b : s.model.bodies) n += b.mesh.num_nodes() * s.model.dim;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(static_cast<long>(s.rows.size()), n), K = Eigen::MatrixXd::Zero(n, n);
  for (size_t r = 0; r < s.rows.size(); ++r)
    for (const ConstraintTerm& t : s.rows[r].terms)
      C(static_cast<long>(r), dof_index(s.model, {t.body, t.node, t.comp})) += t.coef;
  for (const StiffnessEntry& e : k)
    K(dof_index(s.model, {e.body_i, e.node_i, e.comp_i}), dof_index(s.model, {e.body_j, e.node_j, e.comp_j})) +=
        e.value;
  const Eigen::MatrixXd kernel = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
  const Eigen::VectorXd du = kernel * Eigen::VectorXd::LinSpaced(kernel.cols(), 1.0, 2.0);
  const Eigen::VectorXd y = K * du;
  const Eigen::MatrixXd Ct = C.transpose();
  const Eigen::VectorXd in_rows = Ct * Ct.completeOrthogonalDecomposition().solve(y);
  return (y - in_rows).norm() / (K.norm() * du.norm());
}

/// The entries joining two bodies left out (`groups`: each body's own block only).
std::vector<StiffnessEntry> within_bodies(std::vector<StiffnessEntry> k) {
  std::erase_if(k, [](const StiffnessEntry& e) { return e.body_i != e.body_j; });
  return k;
}
}  // namespace

// Why `contact_tangent: full` repeats `none` on a sticking pass to round-off (issue 12): a sticking point's rows hold
// every direction of its relative motion, and its term (the symmetric part of λ ∂C/∂u) maps a motion that keeps the
// rows into range(Cᵀ): it only shifts λ. A slave–master part left out (`groups`) breaks that; a sliding point's
// term (its tangential motion free) is not of that form.
TEST_P(ContactStiffnessDim, StickingPointsTermOnlyShiftsTheMultipliersUnlessCut) {
  const Fixture stick = deformed_state(GetParam(), "sticking");
  const std::vector<StiffnessEntry> k =
      contact_geometric_stiffness(stick.model, stick.pairs, stick.rows, stick.kept, stick.lambda, stick.u);
  ASSERT_FALSE(k.empty());
  EXPECT_LT(outside_rows(stick, k), 1e-12);
  EXPECT_GT(outside_rows(stick, within_bodies(k)), 1e-3);
  const Fixture slide = deformed_state(GetParam(), "frictionless");
  EXPECT_GT(outside_rows(slide, contact_geometric_stiffness(slide.model, slide.pairs, slide.rows, slide.kept,
                                                            slide.lambda, slide.u)),
            1e-3);
}

}  // namespace test_contact_stiffness
