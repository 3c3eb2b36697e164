// A pressure that follows the deformed surface: its load stiffness is the derivative of its nodal forces (checked by
// central differences on a warped, displaced facet in 2D and 3D); at rest it is the dead pressure; through the whole
// pipeline a block squeezed by it on its free faces (symmetry on the others) holds the true stress −p exactly, where
// the dead pressure gives the nominal stress −p and a Cauchy stress larger by the inverse stretch. Small kinematics
// with a follower pressure is refused, naming the field.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/Results.h"
#include "fem/Loads.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_follower_pressure {

using namespace rollsim;

namespace {

constexpr double E = 1000.0, nu = 0.3;

/// A finite-strain elastic block, 2 elements a side over 1 × 1 (× 1), symmetric on its min faces, pressed by p on its
/// max faces, in `steps` increments.
json squeezed_block(int dim, double p, bool follower, int steps = 4) {
  json mesh = {{"type", "block"}, {"nx", 2}, {"ny", 2}, {"lx", 1.0}, {"ly", 1.0}};
  if (dim == 3) mesh.update({{"nz", 2}, {"lz", 1.0}});
  json bcs = json::array();
  const std::string axes = dim == 3 ? "xyz" : "xy";
  for (char a : axes) {
    bcs.push_back(
        {{"type", "symmetry"}, {"body", "b"}, {"set", std::string(1, a) + "min"}, {"normal", std::string(1, a)}});
    bcs.push_back({{"type", "pressure"},
                   {"body", "b"},
                   {"surface", std::string(1, a) + "max"},
                   {"value", p},
                   {"follower", follower}});
  }
  return {{"name", "squeezed"},
          {"dimension", dim},
          {"materials", {{{"name", "m"}, {"E", E}, {"nu", nu}}}},
          {"bodies", {{{"name", "b"}, {"material", "m"}, {"mesh", mesh}, {"kinematics", "finite"}}}},
          {"boundary_conditions", bcs},
          {"analysis", {{"increments", steps}}}};
}

Results run(const json& j) {
  const Project p = parse_project(j.dump(), "test.json");
  return run_project(p, build_model(p));
}

/// The body's mesh and one displacement that moves every node differently (a stretch, a turn and a warp).
Mesh displaced(int dim, Eigen::VectorXd& u) {
  json j = squeezed_block(dim, 1.0, true);
  Mesh m = build_model(parse_project(j.dump(), "b.json")).bodies[0].mesh;
  u.resize(static_cast<Eigen::Index>(m.num_nodes()) * dim);
  for (int n = 0; n < m.num_nodes(); ++n) {
    const auto& x = m.nodes[static_cast<size_t>(n)];
    for (int c = 0; c < dim; ++c)
      u[n * dim + c] = 0.1 * std::sin(1.0 + 2.3 * x[0] + 1.7 * x[1] + 0.9 * x[2] + c) + 0.05 * x[(c + 1) % dim];
  }
  return m;
}

/// Every facet's stiffness against central differences of its nodal forces.
double worst_stiffness_error(int dim) {
  Eigen::VectorXd u;
  const Mesh m = displaced(dim, u);
  const double p = 3.0, h = 1e-6;
  double worst = 0;
  for (const char* s : {"xmax", "ymax"})
    for (const Facet& facet : m.surfaces.at(s)) {
      const std::vector<FollowerPressure> one{{p, {facet}}};
      const Eigen::MatrixXd K = follower_facet_stiffness(m, facet, p, u);
      const int* conn = m.element(facet.element);
      for (int j = 0; j < K.cols(); ++j) {
        const Eigen::Index dof = static_cast<Eigen::Index>(conn[j / dim]) * dim + j % dim;
        Eigen::VectorXd up = u, down = u;
        up[dof] += h;
        down[dof] -= h;
        const Eigen::VectorXd column = (follower_nodal_load(m, one, up) - follower_nodal_load(m, one, down)) / (2 * h);
        for (int i = 0; i < K.rows(); ++i)
          worst = std::max(worst, std::abs(K(i, j) - column[static_cast<Eigen::Index>(conn[i / dim]) * dim + i % dim]));
      }
      EXPECT_GT(K.norm(), p * 1e-3) << "the facet's load moves with its nodes";
    }
  return worst;
}

}  // namespace

TEST(FollowerPressure, ItsStiffnessIsTheDerivativeOfItsNodalForces) {
  EXPECT_LT(worst_stiffness_error(2), 1e-7);
  EXPECT_LT(worst_stiffness_error(3), 1e-7);
}

TEST(FollowerPressure, AtRestItIsTheDeadPressure) {
  for (int dim : {2, 3}) {
    Model dead = build_model(parse_project(squeezed_block(dim, 2.5, false).dump(), "b.json"));
    Model follows = build_model(parse_project(squeezed_block(dim, 2.5, true).dump(), "b.json"));
    const Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(dead.bodies[0].mesh.num_nodes() * dim);
    const Eigen::VectorXd f = follower_nodal_load(follows.bodies[0].mesh, follower_pressures(follows, 0), at_rest);
    EXPECT_LT((f - external_nodal_load(dead, 0)).norm(), 1e-12 * f.norm()) << dim << "D";
    EXPECT_EQ(external_nodal_load(follows, 0).norm(), 0.0) << "a follower pressure is not also a dead load";
  }
}

// Under its own pressure on every free face the block is squeezed uniformly: the follower pressure is the true
// (Cauchy) stress, σ = −p I; the dead one is the nominal stress P = J σ F⁻ᵀ = −p I with F = λ I on the pressed
// axes (λ < 1; plane strain: λ_z = 1), so σ = −p / λ in 2D and −p / λ² in 3D.
TEST(FollowerPressure, ABlockSqueezedByItHoldsTheTrueStress) {
  const double p = 0.08 * E;
  for (int dim : {2, 3}) {
    const Results follows = run(squeezed_block(dim, p, true));
    const Results dead = run(squeezed_block(dim, p, false));
    ASSERT_EQ(follows.status.status, Status::converged) << follows.status.message;
    ASSERT_EQ(dead.status.status, Status::converged) << dead.status.message;
    for (const auto& s : follows.bodies[0].element_stress)
      for (int c = 0; c < dim; ++c) EXPECT_NEAR(s[static_cast<size_t>(c)], -p, 1e-8 * p) << dim << "D, axis " << c;
    const Eigen::VectorXd& u = dead.bodies[0].displacement;
    const double stretch = 1 + u.minCoeff();  // the max corner moves by (λ − 1) × 1 along each axis
    for (const auto& s : dead.bodies[0].element_stress)
      EXPECT_NEAR(s[0], -p / std::pow(stretch, dim - 1), 1e-8 * p) << dim << "D: the dead pressure's Cauchy stress";
    EXPECT_GT(std::abs(-p / stretch + p), 0.01 * p) << "the two loads differ enough to tell apart";
    int iterations = 0;
    for (const auto& inc : follows.increments) iterations = std::max(iterations, inc.newton_iterations);
    EXPECT_LE(iterations, 6) << dim << "D: the load stiffness keeps Newton quadratic on this conservative load";
  }
}

// Torn into subdomains, each facet's load and stiffness go to the subdomain holding its element: FETI and the mixed
// method end where the direct solve does.
TEST(FollowerPressure, EverySolverModeCarriesIt) {
  json j = squeezed_block(2, 0.08 * E, true);
  j["bodies"][0]["mesh"].update({{"nx", 4}, {"ny", 4}});
  const Results direct = run(j);
  ASSERT_EQ(direct.status.status, Status::converged) << direct.status.message;
  for (const char* mode : {"feti", "mixed"}) {
    json m = j;
    m["solver"] = {{"mode", mode}, {"cg_tolerance", 1e-12}};
    if (std::string(mode) == "feti") m["bodies"][0]["partition"] = "2x2";
    const Results r = run(m);
    ASSERT_EQ(r.status.status, Status::converged) << mode << ": " << r.status.message;
    EXPECT_LT((r.bodies[0].displacement - direct.bodies[0].displacement).norm(),
              1e-8 * direct.bodies[0].displacement.norm())
        << mode;
  }
}

TEST(FollowerPressure, OnASmallStrainBodyItIsRefusedNamingTheField) {
  json j = squeezed_block(2, 1.0, true);
  j["bodies"][0]["kinematics"] = "small";
  try {
    build_model(parse_project(j.dump(), "b.json"));
    ADD_FAILURE() << "accepted";
  } catch (const ProjectError& e) {
    ASSERT_FALSE(e.issues().empty());
    EXPECT_EQ(e.issues()[0].path, "boundary_conditions[1].follower") << e.what();
    EXPECT_NE(e.issues()[0].message.find("needs finite kinematics"), std::string::npos) << e.what();
  }
}

}  // namespace test_follower_pressure
