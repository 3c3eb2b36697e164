// The nodal contact pressure of Results (ContactResults): on every body once the model has contact, f·n / tributary
// measure on the slave nodes in contact and 0 everywhere else, so that Σ pressure × tributary measure over the slave
// surface is the pair's normal force — with the tributary lengths / areas computed here from the mesh, not taken
// from the contact search.
#include <gtest/gtest.h>

#include <filesystem>

#include "../../common/TributaryMeasure.h"
#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_contact_pressure {

using namespace rollsim;
using testing_support::tributary_measure;

namespace {

Model sample(const std::string& name) {
  return build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / name));
}

/// Σ pressure × tributary measure over the slave surface of `pair`; checks that no other node carries pressure.
double pressure_resultant(const Model& model, const Results& res, int pair) {
  const ContactPair& p = model.contacts[static_cast<size_t>(pair)];
  const Mesh& slave = model.bodies[static_cast<size_t>(p.slave_body)].mesh;
  const std::map<int, double> measure = tributary_measure(slave, slave.surfaces.at(p.slave_surface));
  const Eigen::VectorXd& pressure = res.bodies[static_cast<size_t>(p.slave_body)].contact_pressure;
  double sum = 0;
  for (int n = 0; n < slave.num_nodes(); ++n) {
    const auto it = measure.find(n);
    if (it == measure.end())
      EXPECT_EQ(pressure[n], 0.0) << "node " << n << " is not on the slave surface";
    else
      sum += pressure[n] * it->second;
  }
  return sum;
}

}  // namespace

TEST(ContactPressure, IntegratesToTheNormalForceOfTheHertzPair) {
  const Model model = sample("cylinder-indent-2d.json");
  auto solver = make_solver("mixed", {1e-8, 1});
  const Results res = run_linear_static(model, *solver);
  ASSERT_EQ(to_string(res.status.status), std::string("converged"));
  ASSERT_EQ(res.contacts.size(), 1u);
  const ContactResult& c = res.contacts[0];
  EXPECT_NEAR(c.normal_force, 4.32 / 2, 0.01 * 4.32 / 2) << "the half model carries half the line force";
  EXPECT_NEAR(pressure_resultant(model, res, 0), c.normal_force, 1e-10 * c.normal_force);
  // every body carries the field; the master (cylinder) is free of it, the peak is the reported max_pressure
  for (size_t b = 0; b < model.bodies.size(); ++b)
    ASSERT_EQ(res.bodies[b].contact_pressure.size(), model.bodies[b].mesh.num_nodes());
  EXPECT_EQ(res.bodies[1].contact_pressure.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_DOUBLE_EQ(res.bodies[0].contact_pressure.maxCoeff(), c.max_pressure);
  EXPECT_GE(res.bodies[0].contact_pressure.minCoeff(), 0.0) << "frictionless contact: compression only";
}

TEST(ContactPressure, IntegratesToTheNormalForceOnAThreeDimensionalTiedPair) {
  const Model model = sample("block-indent-3d-10x6x4.json");
  auto solver = make_solver("direct", {});
  const Results res = run_linear_static(model, *solver);
  ASSERT_EQ(res.contacts.size(), 1u);
  const double fn = res.contacts[0].normal_force;
  ASSERT_GT(std::abs(fn), 0);
  EXPECT_NEAR(pressure_resultant(model, res, 0), fn, 1e-10 * std::abs(fn));
}

TEST(ContactPressure, AbsentWithoutContactPairs) {
  const Model model = sample("plate-hole-2d.json");
  auto solver = make_solver("direct", {});
  const Results res = run_linear_static(model, *solver);
  for (const BodyResults& b : res.bodies) EXPECT_EQ(b.contact_pressure.size(), 0);
}

}  // namespace test_contact_pressure
