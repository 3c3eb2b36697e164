// A Newton run that remeshes (analysis/Remeshing): restarted from its current configuration after every step, a
// homogeneous compression gives its own mesh's force at every step to round-off; upsetting between sticking faces,
// which stops at 56 % on its own mesh, is upset to the end; the project checks refuse what a remesh cannot carry, at
// the user's paths.
#include <gtest/gtest.h>

#include <cmath>

#include "../../common/RunJson.h"
#include "analysis/Remeshing.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_remeshing {

using namespace rollsim;
using json = nlohmann::json;
using testing_support::run_json;

namespace {
json upsetting(int n, double stroke, int increments) {
  const json mesh = {{"type", "block"}, {"nx", n}, {"ny", n}, {"lx", 10.0}, {"ly", 10.0}};
  return {
      {"name", "upsetting"},
      {"dimension", 2},
      {"materials",
       {{{"name", "steel"}, {"E", 200e3}, {"nu", 0.3}, {"yield_stress", 250.0}, {"hardening_modulus", 2000.0}}}},
      {"bodies",
       {{{"name", "block"}, {"material", "steel"}, {"formulation", "bbar"}, {"kinematics", "finite"}, {"mesh", mesh}}}},
      {"boundary_conditions",
       json::array({{{"type", "displacement"}, {"body", "block"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
                    {{"type", "displacement"}, {"body", "block"}, {"set", "ymax"}, {"ux", 0.0}, {"uy", -stroke}}})},
      {"analysis", {{"type", "newton"}, {"increments", increments}}},
      {"solver", {{"mode", "direct"}}}};
}

/// The platen's force (the ymax nodes' reactions, y) of an increment, on the model it was computed on.
double platen_force(const Model& run_model, const IncrementResults& inc) {
  const Model& m = model_of(inc, run_model);
  double f = 0;
  for (int n : m.bodies[0].mesh.node_sets.at("ymax")) f += inc.bodies[0].nodal_force[n * 2 + 1];
  return f;
}

std::vector<std::string> issues_of(const json& j) {
  std::vector<std::string> out;
  try {
    const Project p = parse_project(j.dump(), "test.json");
    build_model(p);
  } catch (const ProjectError& e) {
    for (const Issue& i : e.issues()) out.push_back(i.str());
  }
  return out;
}

bool has(const std::vector<std::string>& issues, const std::string& text) {
  for (const std::string& i : issues)
    if (i.find(text) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST(Remeshing, AfterEveryStepTheSameForceAsItsOwnMesh) {
  // a homogeneous compression on rollers: remeshing after every step (remesh_quality 1: any element compressed at all)
  // moves no node (the motion is affine) and carries every point's state exactly — the restart from the current
  // configuration is the run itself, to round-off, only when the stress per reference volume carries the plastic
  // volume the new reference holds (J2Plasticity::rebase_state: without it 0.33 % off at 30 %)
  json j = upsetting(4, 3.0, 10);
  j["boundary_conditions"] =
      json::array({{{"type", "displacement"}, {"body", "block"}, {"set", "ymin"}, {"uy", 0.0}},
                   {{"type", "displacement"}, {"body", "block"}, {"set", "xmin"}, {"ux", 0.0}},
                   {{"type", "displacement"}, {"body", "block"}, {"set", "ymax"}, {"uy", -3.0}}});
  const Project plain_project = parse_project(j.dump(), "test.json");
  const Model plain_model = build_model(plain_project);
  const Results plain = run_project(plain_project, plain_model, nullptr);
  j["analysis"]["remesh_quality"] = 1.0;
  const Project p = parse_project(j.dump(), "test.json");
  const Model model = build_model(p);
  const Results r = run_project(p, model, nullptr);
  ASSERT_EQ(plain.status.status, Status::converged) << plain.status.message;
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  EXPECT_GE(r.remeshes.size(), 5u);
  for (const RemeshRecord& m : r.remeshes) {
    EXPECT_EQ(m.nodes_kept, "");
    EXPECT_NEAR(m.plastic_strain_integral_after, m.plastic_strain_integral_before,
                1e-9 * m.plastic_strain_integral_before);
  }
  ASSERT_EQ(r.increments.size(), plain.increments.size());
  for (size_t i = 0; i < r.increments.size(); ++i) {
    EXPECT_NEAR(r.increments[i].load_factor, plain.increments[i].load_factor, 1e-12);
    EXPECT_NEAR(platen_force(model, r.increments[i]) / platen_force(plain_model, plain.increments[i]), 1.0, 1e-9)
        << "increment " << i + 1;
  }
}

TEST(Remeshing, AfterEveryStepTheSameHeatAsItsOwnMesh) {
  // the same compression conducting heat over 1 s (plastic work heats it, the air on its free side cools it): the
  // temperatures carried across every restart — the nodes', the points' rises, what is left of the time — are its own
  // mesh's to 1e-9 of the rise, once HeatConduction's capacity and plastic heat take each point's mass as J_p times
  // its reference volume (a restart's reference is the current, elastically compressed one: without it 4e-5)
  json j = upsetting(4, 3.0, 10);
  j["materials"][0].update({{"conductivity", 30.0}, {"heat_capacity", 4.5}, {"temperature", 20.0}});
  j["boundary_conditions"] =
      json::array({{{"type", "displacement"}, {"body", "block"}, {"set", "ymin"}, {"uy", 0.0}},
                   {{"type", "displacement"}, {"body", "block"}, {"set", "xmin"}, {"ux", 0.0}},
                   {{"type", "displacement"}, {"body", "block"}, {"set", "ymax"}, {"uy", -3.0}}});
  j["heat"] = {{"ambient_temperature", 20.0}, {"air", {{{"body", "block"}, {"surface", "xmax"}, {"convection", 0.5}}}}};
  j["analysis"]["duration"] = 1.0;
  const Results plain = run_json(j);
  j["analysis"]["remesh_quality"] = 1.0;
  const Results r = run_json(j);
  ASSERT_EQ(plain.status.status, Status::converged) << plain.status.message;
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  EXPECT_GE(r.remeshes.size(), 5u);
  const Eigen::VectorXd &T = r.bodies[0].nodal_temperature, &T0 = plain.bodies[0].nodal_temperature;
  ASSERT_EQ(T.size(), T0.size());
  EXPECT_GT(T0.maxCoeff(), 30.0);  // the plastic work heated it
  EXPECT_LT((T - T0).cwiseAbs().maxCoeff(), 1e-9 * (T0.maxCoeff() - 20.0)) << (T - T0).cwiseAbs().maxCoeff();
}

TEST(Remeshing, UpsetsPastWhereItsOwnMeshStops) {
  // plane-strain upsetting between sticking faces, 50 % in 50 steps on 20 × 20: on its own mesh the side folds over
  // the platens' planes at the pinned corners and Newton stops at 56 %; remeshed, each fold is laid onto its face and
  // the corner follows (mesh/EvenNodes), and the whole stroke is upset
  const json j = upsetting(20, 5.0, 50);
  const Project plain_project = parse_project(j.dump(), "test.json");
  const Model plain_model = build_model(plain_project);
  const Results plain = run_project(plain_project, plain_model, nullptr);
  ASSERT_NE(plain.status.status, Status::converged) << "the mesh alone no longer stops early";
  EXPECT_LT(plain.increments.back().load_factor, 0.6);

  json remeshed = j;
  remeshed["analysis"]["remesh_quality"] = 0.5;
  const Project p = parse_project(remeshed.dump(), "test.json");
  const Model model = build_model(p);
  const Results r = run_project(p, model, nullptr);
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  EXPECT_DOUBLE_EQ(r.increments.back().load_factor, 1.0);
  ASSERT_GE(r.remeshes.size(), 4u);
  int unfolded = 0;  // remeshes that laid a fold onto its face: the worst corner sine from ≤ 0 to a shape
  for (const RemeshRecord& m : r.remeshes) {
    EXPECT_EQ(m.nodes_kept, "") << "at load factor " << m.load_factor;
    EXPECT_NEAR(m.plastic_strain_integral_after / m.plastic_strain_integral_before, 1.0, 0.01);
    EXPECT_LE(m.plastic_strain_max_after, m.plastic_strain_max_before * (1 + 1e-12));
    unfolded += m.shape_before <= 0 && m.shape_after > 0.2;
  }
  EXPECT_GE(unfolded, 2);
  // up to the first remesh the two runs are one
  for (size_t i = 0; i < plain.increments.size(); ++i) {
    if (r.increments[i].load_factor > r.remeshes.front().load_factor + 1e-12) break;
    EXPECT_NEAR(platen_force(model, r.increments[i]) / platen_force(plain_model, plain.increments[i]), 1.0, 1e-9);
  }
}

TEST(Remeshing, ARunNeverGoesOnFromAFoldedShape) {
  // a flat punch 10 mm into a plastic base on rollers (20 × 12): at 92.5 % the surface element at the punch's corner
  // has folded (its nodes are the contact's, which stay) — restarted from that shape the punch's force fell by 40 % in
  // one step; the run ends there instead, saying why
  const json base_mesh = {{"type", "block"}, {"nx", 20}, {"ny", 12}, {"lx", 50.0}, {"ly", 30.0}};
  const json punch_mesh = {{"type", "block"}, {"nx", 4}, {"ny", 4}, {"lx", 10.0}, {"ly", 8.0}, {"origin", {0.0, 30.0}}};
  const json j = {
      {"name", "punch"},
      {"dimension", 2},
      {"materials",
       {{{"name", "base"}, {"E", 200e3}, {"nu", 0.3}, {"yield_stress", 250.0}, {"hardening_modulus", 2000.0}},
        {{"name", "tool"}, {"E", 2e6}, {"nu", 0.3}}}},
      {"bodies",
       {{{"name", "base"},
         {"material", "base"},
         {"formulation", "bbar"},
         {"kinematics", "finite"},
         {"mesh", base_mesh}},
        {{"name", "punch"}, {"material", "tool"}, {"kinematics", "finite"}, {"mesh", punch_mesh}}}},
      {"contacts",
       {{{"name", "punch-base"},
         {"type", "frictionless"},
         {"slave_body", "base"},
         {"slave_surface", "ymax"},
         {"master_body", "punch"},
         {"master_surface", "ymin"},
         {"search_distance", 5.0},
         {"sliding", "large"}}}},
      {"boundary_conditions",
       {{{"type", "displacement"}, {"body", "base"}, {"set", "ymin"}, {"uy", 0.0}},
        {{"type", "symmetry"}, {"body", "base"}, {"set", "xmin"}, {"normal", "x"}},
        {{"type", "symmetry"}, {"body", "punch"}, {"set", "xmin"}, {"normal", "x"}},
        {{"type", "displacement"}, {"body", "punch"}, {"set", "ymax"}, {"ux", 0.0}, {"uy", -10.0}}}},
      {"analysis", {{"type", "newton"}, {"increments", 40}, {"remesh_quality", 0.5}}},
      {"solver", {{"mode", "direct"}}}};
  const Results r = run_json(j);
  ASSERT_EQ(r.status.status, Status::diverged) << r.status.message;
  EXPECT_NE(r.status.message.find("cannot be remeshed: element "), std::string::npos) << r.status.message;
  EXPECT_NE(r.status.message.find("a run cannot go on from a folded shape"), std::string::npos) << r.status.message;
  ASSERT_GE(r.increments.size(), 2u);
  // the contact's force grew at every step to the end
  for (size_t i = 1; i < r.increments.size(); ++i)
    EXPECT_GT(r.increments[i].contacts.at(0).normal_force, r.increments[i - 1].contacts.at(0).normal_force)
        << "increment " << i + 1;
}

TEST(Remeshing, RefusesWhatARemeshCannotCarryAtTheUsersPaths) {
  json elastic = upsetting(4, 1.0, 4);
  elastic["analysis"]["remesh_quality"] = 0.5;
  elastic["materials"].push_back({{"name", "tool"}, {"E", 210e3}, {"nu", 0.3}});
  elastic["bodies"].push_back({{"name", "platen"},
                               {"material", "tool"},
                               {"mesh", {{"type", "block"}, {"nx", 2}, {"ny", 1}, {"lx", 12.0}, {"ly", 1.0}}}});
  elastic["boundary_conditions"].push_back(
      {{"type", "displacement"}, {"body", "platen"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}});
  EXPECT_TRUE(has(issues_of(elastic), "bodies[1].kinematics: body 'platen' is small-strain"));

  json loaded = upsetting(4, 1.0, 4);
  loaded["analysis"]["remesh_quality"] = 0.5;
  loaded["boundary_conditions"].push_back({{"type", "force"}, {"body", "block"}, {"set", "xmax"}, {"fx", 1.0}});
  EXPECT_TRUE(has(issues_of(loaded), "boundary_conditions[2]: a force load cannot be carried across a remesh"));

  json solid = upsetting(2, 1.0, 2);
  solid["dimension"] = 3;
  solid["bodies"][0]["mesh"].update({{"nz", 2}, {"lz", 10.0}});
  solid["analysis"]["remesh_quality"] = 0.5;
  EXPECT_TRUE(has(issues_of(solid), "analysis.remesh_quality: only 2D quad meshes can be remeshed yet"));
}

}  // namespace test_remeshing
