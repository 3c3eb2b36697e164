// The rolling process section: the paper's pass generates a pre-bitten slab (its front end at the exit plane, its
// top cut to the roll's polygon over the arc) and a roll, half thickness (and half width in 3D) by symmetry;
// bad process values are refused with their JSON path; grading toward the roll gap moves the slab's nodes only.
// What the pass would ignore (a material no body uses, μ without Coulomb friction) or cannot build (a slab wider than
// the barrel, a hub outside the roll) is refused at the user's own path, never a generated body's. A hot pass takes
// its slab's flow stress law, temperature and the roll's time, and refuses what it lacks or would ignore.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "../../../common/RunJson.h"
#include "contact/ContactConstraints.h"
#include "material/FlowStress.h"
#include "mesh/Mesh.h"
#include "process/rolling/RollingHeat.h"
#include "process/rolling/RollingProcess.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunConfig.h"

namespace test_rolling_process {

using namespace rollsim;

namespace {
Model rolling(int dim, json process = json::object()) {
  process["type"] = "rolling";
  json j = {{"dimension", dim}, {"process", process}};
  return build_model(parse_project(j.dump(), "rolling"));
}

/// The pass as its measures see it, on the model rolling(dim, process) builds.
RollingPass pass_of(int dim, json process = json::object()) {
  process["type"] = "rolling";
  json j = {{"dimension", dim}, {"process", process}};
  const Project p = parse_project(j.dump(), "rolling");
  return rolling_pass(p.data.at("process"), build_model(p));
}

// Distinct x of the slab's nodes, ascending: the node planes along the rolling direction.
std::vector<double> x_planes(const Mesh& m) {
  std::vector<double> x;
  for (const auto& p : m.nodes) x.push_back(p[0]);
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  return x;
}

std::string refusal(const json& process, int dim = 2, json extra = json::object()) {
  json j = {{"dimension", dim}, {"process", process}};
  j.update(extra);
  return testing_support::refusal_of(j);
}
}  // namespace

TEST(RollingProcess, GeneratesAPreBittenSlabTouchingTheRollAlongTheArc) {
  const double bite = std::sqrt(300.0 * 300.0 - (300 - 6.6) * (300 - 6.6));  // x of the entry, 62.6 mm
  for (const int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const Model m = rolling(dim);
    ASSERT_EQ(m.bodies.size(), 2u);
    EXPECT_EQ(m.bodies[0].name, "slab");
    EXPECT_EQ(m.bodies[1].name, "roll");
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_EQ(m.contacts[0].kind, ContactKind::Sticking);
    EXPECT_EQ(m.contacts[0].shear_limit, 0.0);  // the paper's sticking: no slip, the slab's shear yield limits it
    const Model c = rolling(dim, {{"friction", "coulomb"}, {"friction_coefficient", 0.4}});
    EXPECT_EQ(c.contacts[0].kind, ContactKind::Coulomb);
    EXPECT_EQ(c.contacts[0].friction, 0.4);
    EXPECT_NEAR(c.contacts[0].shear_limit, 100 / std::sqrt(3.0), 1e-12);  // μ p capped at k = σ_0/√3
    EXPECT_TRUE(m.contacts[0].holds_slave);                               // the rear end is free: friction draws it
    EXPECT_EQ(m.displacements[static_cast<size_t>(pass_of(dim).hub)].set, "inner");
    // the slab's top nodes over the arc lie on the roll's polygon (active from the start), none penetrates it
    const auto pairs = search_contacts(m);
    int on_arc = 0, active = 0;
    for (size_t j = 0; j < pairs[0].points.size(); ++j) {
      const ContactPoint& c = pairs[0].points[j];
      const double x = m.bodies[0].mesh.nodes[static_cast<size_t>(c.slave_node)][0];
      EXPECT_GE(c.gap, -1e-9);
      if (x > -bite + 1e-9) EXPECT_LE(std::abs(c.gap), 1e-9) << "node " << c.slave_node << " at x = " << x;
      on_arc += x > -bite + 1e-9;
      active += pairs[0].active[j];
    }
    EXPECT_GT(on_arc, 0);
    EXPECT_GE(active, on_arc);
    // half thickness 50 mm behind the bite, 43.4 mm (the exit's) at the front end x = 0, the roll's lowest point
    double rear = -1e300, front = -1e300, front_x = -1e300, roll_bottom = 1e300;
    const int up = dim == 2 ? 1 : 2;
    for (const auto& x : m.bodies[0].mesh.nodes) {
      if (x[0] < -bite) rear = std::max(rear, x[up]);
      front_x = std::max(front_x, x[0]);
    }
    for (const auto& x : m.bodies[0].mesh.nodes)
      if (x[0] == front_x) front = std::max(front, x[up]);
    for (const auto& x : m.bodies[1].mesh.nodes) roll_bottom = std::min(roll_bottom, x[up]);
    EXPECT_NEAR(rear, 50.0, 1e-9);
    EXPECT_EQ(front_x, 0.0);
    EXPECT_NEAR(front, 43.4, 1e-9);
    EXPECT_NEAR(roll_bottom, 43.4, 1e-9);
  }
}

// process.roll_mesh: fixed — the roll stays where it is meshed (its hub turned by 0, small kinematics: linear) and
// its surface's material turns by travel / R through the contact (master_turns about the hub's axis); the slab is cut
// to the roll's circle, which the contact holds it to, not to its chords. A pass with heat is refused (the roll's
// heat would stay where its mesh is), and one that remeshes (the small-strain roll would lose its stress).
TEST(RollingProcess, AFixedRollStaysWhereItIsMeshedAndItsSurfaceTurns) {
  for (const int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const Model m = rolling(dim, {{"roll_mesh", "fixed"}});
    EXPECT_EQ(m.bodies[1].kinematics, Kinematics::Small);
    EXPECT_EQ(rolling(dim).bodies[1].kinematics, Kinematics::Finite);
    const DisplacementBC& hub = m.displacements[static_cast<size_t>(pass_of(dim, {{"roll_mesh", "fixed"}}).hub)];
    EXPECT_EQ(hub.rotation->angle, 0.0);
    ASSERT_TRUE(m.contacts[0].master_turns.has_value());
    EXPECT_NEAR(m.contacts[0].master_turns->angle, 100.0 / 300.0, 1e-12);  // the default 100 mm of travel on R 300
    EXPECT_EQ(m.contacts[0].master_turns->center, hub.rotation->center);
    EXPECT_EQ(m.contacts[0].master_turns->axis, hub.rotation->axis);
    EXPECT_FALSE(rolling(dim).contacts[0].master_turns.has_value());
    const int up = dim - 1;
    const double axis = hub.rotation->center[static_cast<size_t>(up)];
    int on_circle = 0;  // the top over the arc, cut to the circle (the turning roll's slab: to its chords)
    for (const auto& x : m.bodies[0].mesh.nodes) {
      const double circle = axis - std::sqrt(300.0 * 300.0 - x[0] * x[0]), h = x[static_cast<size_t>(up)];
      if (x[0] <= -60 || x[0] >= 0 || std::abs(h - circle) > 1) continue;
      EXPECT_NEAR(h, circle, 1e-9);
      ++on_circle;
    }
    EXPECT_GT(on_circle, 0);
  }
  const std::string heat =
      refusal({{"type", "rolling"}, {"roll_mesh", "fixed"}, {"heat_transfer", json::object()}, {"roll_speed", 30.0}});
  EXPECT_NE(heat.find("process.roll_mesh: fixed is not for a pass with heat_transfer"), std::string::npos) << heat;
  const std::string remesh =
      refusal({{"type", "rolling"}, {"roll_mesh", "fixed"}}, 2, {{"analysis", {{"remesh_quality", 0.5}}}});
  EXPECT_NE(remesh.find("process.roll_mesh: fixed is not for a pass that remeshes"), std::string::npos) << remesh;
}

TEST(RollingProcess, ExitThicknessInsteadOfReduction) {
  // the paper's 13.2 % given as the exit thickness 86.8 mm builds the same pass, node for node
  const Model by_reduction = rolling(2), by_exit = rolling(2, {{"exit_thickness", 86.8}});
  EXPECT_DOUBLE_EQ(pass_of(2, {{"exit_thickness", 86.8}}).exit_thickness, 86.8);
  EXPECT_NEAR(pass_of(2).exit_thickness, 86.8, 1e-12);
  for (size_t b = 0; b < 2; ++b)
    for (size_t n = 0; n < by_exit.bodies[b].mesh.nodes.size(); ++n)
      for (int c = 0; c < 2; ++c)
        EXPECT_NEAR(by_exit.bodies[b].mesh.nodes[n][c], by_reduction.bodies[b].mesh.nodes[n][c], 1e-9) << b << " " << n;
  const Model heavier = rolling(2, {{"exit_thickness", 80.0}});
  double roll_bottom = 1e300;
  for (const auto& x : heavier.bodies[1].mesh.nodes) roll_bottom = std::min(roll_bottom, x[1]);
  EXPECT_NEAR(roll_bottom, 40.0, 1e-9);
  // one of the two, and a thickness the roll can reach
  const std::string both = refusal({{"type", "rolling"}, {"reduction", 0.1}, {"exit_thickness", 90.0}});
  EXPECT_NE(both.find("process.exit_thickness: give either process.reduction or process.exit_thickness"),
            std::string::npos)
      << both;
  EXPECT_NE(refusal({{"type", "rolling"}, {"exit_thickness", 120.0}}).find("process.exit_thickness: must be below"),
            std::string::npos);
  EXPECT_NE(refusal({{"type", "rolling"}, {"exit_thickness", 5.0}}).find("process.exit_thickness: must be below"),
            std::string::npos);
}

TEST(RollingProcess, BadValuesNameTheirPath) {
  json j = {{"dimension", 2}, {"process", {{"reduction", 1.5}}}};
  try {
    parse_project(j.dump(), "bad");
    FAIL() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("process.reduction"), std::string::npos) << e.what();
  }
  json none = {{"dimension", 2}};
  try {
    parse_project(none.dump(), "empty");
    FAIL() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("no body: give `bodies` or a `process`"), std::string::npos) << e.what();
  }
}

TEST(RollingProcess, SlabPartitionBySpecOrPaintedMap) {
  json j = {{"dimension", 2}, {"process", {{"type", "rolling"}, {"slab_nx", 4}, {"slab_nt", 2}}}};
  j["process"]["slab_partition"] = "2x1";
  const Model sliced = build_model(parse_project(j.dump(), "rolling"));
  ASSERT_EQ(sliced.bodies[0].partition.num_subdomains, 2);
  j["process"].erase("slab_partition");
  j["process"]["slab_partition_map"] = sliced.bodies[0].partition.element_subdomain;
  const Model painted = build_model(parse_project(j.dump(), "rolling"));
  EXPECT_EQ(painted.bodies[0].partition.element_subdomain, sliced.bodies[0].partition.element_subdomain);
  EXPECT_EQ(painted.bodies[1].partition.num_subdomains, 1);  // the roll stays one domain
}

TEST(RollingProcess, GradingOneKeepsTodaysUniformNodesBitForBit) {
  for (const int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const Model plain = rolling(dim), graded_one = rolling(dim, {{"grading", 1.0}});
    const Mesh &a = plain.bodies[0].mesh, &b = graded_one.bodies[0].mesh;
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(a.connectivity, b.connectivity);
    const double L = 300, x0 = x_planes(a).front();
    const auto planes = x_planes(a);
    ASSERT_EQ(planes.size(), 49u);
    for (size_t n = 0; n < a.nodes.size(); ++n) {
      EXPECT_EQ(a.nodes[n], b.nodes[n]) << n;  // exact equality, not a tolerance
    }
    for (int i = 0; i <= 48; ++i) EXPECT_EQ(planes[i], x0 + L * i / 48) << i;  // the uniform generator's expression
  }
}

TEST(RollingProcess, GradingShrinksSlabElementsGeometricallyTowardTheGap) {
  const double r = 1.05;
  for (const int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const Model uniform = rolling(dim), graded = rolling(dim, {{"grading", r}});
    const Mesh &u = uniform.bodies[0].mesh, &g = graded.bodies[0].mesh;
    // same elements, same node numbering and connectivity; only x moves
    EXPECT_EQ(g.num_elements(), u.num_elements());
    EXPECT_EQ(g.connectivity, u.connectivity);
    ASSERT_EQ(g.nodes.size(), u.nodes.size());
    const double bite = std::sqrt(300.0 * 300.0 - (300 - 6.6) * (300 - 6.6));
    for (size_t n = 0; n < g.nodes.size(); ++n)  // behind the bite; over the arc the roll's cut depends on x
      if (g.nodes[n][0] < -bite && u.nodes[n][0] < -bite)
        for (int c = 1; c < 3; ++c) EXPECT_EQ(g.nodes[n][c], u.nodes[n][c]);
    const auto xu = x_planes(u), x = x_planes(g);
    ASSERT_EQ(x.size(), xu.size());
    EXPECT_EQ(x.front(), xu.front());  // rear end and front end (the gap) where they were: the length is unchanged
    EXPECT_EQ(x.back(), xu.back());
    EXPECT_EQ(x.back(), 0.0);  // the front end at the exit plane (the pre-bitten slab)
    const size_t n = x.size() - 1;
    for (size_t i = 0; i + 1 < n; ++i) {
      const double h = x[i + 1] - x[i], next = x[i + 2] - x[i + 1];
      EXPECT_NEAR(h / next, r, 1e-9) << i;  // each element r times its neighbour nearer the gap
    }
    const double smallest = x[n] - x[n - 1], largest = x[1] - x[0];
    // h_min = L (r − 1) / (r^n − 1): the geometric series of n sizes sums to the slab length
    EXPECT_NEAR(smallest, 300 * (r - 1) / (std::pow(r, n) - 1), 1e-9);
    EXPECT_NEAR(largest / smallest, std::pow(r, n - 1), 1e-6);
    check_element_orientation(g);  // every corner Jacobian positive (throws otherwise)
    // the contact search still finds the front edge on the roll
    const auto pairs = search_contacts(graded);
    double gap = 1e300;
    for (const ContactPoint& c : pairs[0].points) gap = std::min(gap, c.gap);
    EXPECT_GE(gap, -1e-9);
  }
}

TEST(RollingProcess, BadGradingIsRefusedNamingTheField) {
  for (const json& bad : {json(0.5), json(3.0), json("x"), json(0.0)}) {
    const std::string why = refusal({{"type", "rolling"}, {"grading", bad}});
    EXPECT_NE(why.find("process.grading"), std::string::npos) << why;
  }
  EXPECT_NE(refusal({{"type", "rolling"}, {"grading", 0.5}}).find("in [1, 2]"), std::string::npos);
  // 2^47: the smallest element would be round-off next to the largest
  const std::string spread = refusal({{"type", "rolling"}, {"grading", 2.0}, {"slab_nx", 48}});
  EXPECT_NE(spread.find("process.grading: 2 over 48 elements"), std::string::npos) << spread;
  EXPECT_EQ(spread.find("bodies["), std::string::npos) << spread;  // not repeated under the generated body
}

// process.width_symmetry: false models the whole width about y = 0 — twice the slab's and the roll's elements across
// it, no symmetry plane at y = 0 but the slab's centre line (y = 0 on its mid-plane) held sideways — and the pass's
// measures then count the model once instead of twice.
TEST(RollingProcess, WholeWidthMirrorsSlabAndRollAndHoldsTheCentreLine) {
  const json small = {{"slab_nx", 4}, {"slab_nw", 2}, {"slab_nt", 2}, {"roll_n_axial", 2}, {"roll_n_around", 48}};
  json whole_spec = small;
  whole_spec["width_symmetry"] = false;
  const Model half = rolling(3, small), whole = rolling(3, whole_spec);
  for (size_t b = 0; b < 2; ++b)
    EXPECT_EQ(whole.bodies[b].mesh.num_elements(), 2 * half.bodies[b].mesh.num_elements()) << b;
  double lo = 1e300, hi = -1e300;
  for (const auto& x : whole.bodies[0].mesh.nodes) lo = std::min(lo, x[1]), hi = std::max(hi, x[1]);
  EXPECT_NEAR(lo, -175.0, 1e-9);
  EXPECT_NEAR(hi, 175.0, 1e-9);
  const std::vector<int>& line = whole.bodies[0].mesh.node_sets.at("centre_line");
  EXPECT_EQ(line.size(), 5u);  // slab_nx + 1 nodes at y = 0, z = 0
  for (int n : line) {
    EXPECT_NEAR(whole.bodies[0].mesh.nodes[static_cast<size_t>(n)][1], 0.0, 1e-9);
    EXPECT_NEAR(whole.bodies[0].mesh.nodes[static_cast<size_t>(n)][2], 0.0, 1e-9);
  }
  EXPECT_TRUE(pass_of(3, small).half_width);
  EXPECT_FALSE(pass_of(3, whole_spec).half_width);
  EXPECT_FALSE(pass_of(2, {{"width_symmetry", false}}).half_width);  // plane strain has no width
}

TEST(RollingProcess, WhatThePassWouldIgnoreIsRefusedNamingIt) {
  const json steel = {{"name", "steel"}, {"E", 210000.0}, {"nu", 0.3}};
  const std::string material = refusal({{"type", "rolling"}}, 2, {{"materials", {steel}}});
  EXPECT_NE(material.find("materials[0]: 'steel' is used by no body: a rolling pass makes its own materials from "
                          "process.slab_E"),
            std::string::npos)
      << material;
  for (const std::string friction : {"sticking", "frictionless"}) {
    const std::string mu = refusal({{"type", "rolling"}, {"friction", friction}, {"friction_coefficient", 0.35}});
    EXPECT_NE(mu.find("process.friction_coefficient: has no effect with process.friction: " + friction),
              std::string::npos)
        << mu;
  }
  EXPECT_EQ(refusal({{"type", "rolling"}, {"friction", "coulomb"}, {"friction_coefficient", 0.35}}), "accepted");
  EXPECT_EQ(pass_of(2, {{"friction", "coulomb"}}).friction, 0.3);  // μ's default under Coulomb friction
}

TEST(RollingProcess, AHotPassTakesItsFlowStressLawItsTemperatureAndTheRollsTime) {
  const json shida = {{"law", "shida"}, {"carbon", 0.2}};
  const json hot = {{"slab_flow_stress", shida},
                    {"slab_temperature", 1050.0},
                    {"reduction", 0.2},
                    {"roll_speed", 30.0},
                    {"slab_heat_capacity", 4.9}};
  const Model model = rolling(2, hot);
  const MaterialData& slab = model.bodies[0].material;
  EXPECT_EQ(slab.flow_stress.law, "shida");
  EXPECT_EQ(slab.temperature, 1050.0);
  EXPECT_EQ(slab.heat_capacity, 4.9);
  EXPECT_EQ(model.bodies[1].material.heat_capacity, 0.0) << "the roll is elastic: nothing heats it";
  EXPECT_EQ(slab.yield_stress, 0.0);
  // Sims's flow stress: the law's mean over ε 0 → (2/√3) ln(1.25) at ε̇ = ε ωR / √(R Δh), by a finer trapezoid rule
  const RollingPass pass = pass_of(2, hot);
  const double strain = 2 / std::sqrt(3.0) * std::log(1.25), v = 30 * 2 * M_PI / 60 * 300;
  const double rate = strain * v / std::sqrt(300 * 20.0);
  EXPECT_NEAR(pass.mean_strain_rate, rate, 1e-12 * rate);
  const auto law = make_flow_stress(slab);
  double mean = 0;
  const int n = 4000;
  for (int i = 0; i <= n; ++i) mean += (i == 0 || i == n ? 0.5 : 1.0) * law->at(strain * i / n, rate, 1050).stress / n;
  EXPECT_NEAR(pass.flow_stress, mean, 1e-4 * mean);
  json j = {{"dimension", 2}, {"process", hot}};
  j["process"]["type"] = "rolling";
  EXPECT_NEAR(read_run_config(parse_project(j.dump(), "hot").data).newton.duration, 100 / v, 1e-12);  // travel / ωR
}

TEST(RollingProcess, AHotPassesMissingOrIdleFieldsAreRefusedAtTheProcesssPath) {
  const json shida = {{"law", "shida"}, {"carbon", 0.2}};
  const std::string speed = refusal({{"type", "rolling"}, {"slab_flow_stress", shida}});
  EXPECT_NE(speed.find("process.roll_speed: is needed: the slab's flow stress law (shida) depends on the strain rate"),
            std::string::npos)
      << speed;
  const std::string idle = refusal({{"type", "rolling"}, {"slab_temperature", 1100.0}});
  EXPECT_NE(idle.find("process.slab_temperature: has no effect without process.slab_flow_stress"), std::string::npos)
      << idle;
  const std::string hardening =
      refusal({{"type", "rolling"}, {"slab_flow_stress", shida}, {"roll_speed", 30.0}, {"slab_hardening", 300.0}});
  EXPECT_NE(hardening.find("process.slab_hardening: has no effect with process.slab_flow_stress"), std::string::npos)
      << hardening;
  const std::string duration =
      refusal({{"type", "rolling"}, {"roll_speed", 30.0}}, 2, {{"analysis", {{"duration", 2.0}}}});
  EXPECT_NE(duration.find("analysis.duration: a rolling pass's time follows from process.roll_speed"),
            std::string::npos)
      << duration;
  const std::string cold =
      refusal({{"type", "rolling"}, {"slab_flow_stress", shida}, {"roll_speed", 30.0}, {"slab_temperature", 500.0}});
  EXPECT_EQ(cold, "accepted") << "outside Shida's range is a warning of the run, not a refusal";
  const Model model = rolling(2, {{"slab_flow_stress", shida}, {"roll_speed", 30.0}, {"slab_temperature", 500.0}});
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_EQ(model.warnings[0].rfind("process (its material 'slab'): 500 °C is outside the range the shida law", 0), 0u)
      << model.warnings[0] << ": the generated material's path is not in the user's file";
}

TEST(RollingProcess, HeatTransferMakesTheSlabAndTheRollConductAndTheAirCoolTheSlabsFreeFaces) {
  const json shida = {{"law", "shida"}, {"carbon", 0.2}};
  const json heat = {{"slab_flow_stress", shida},
                     {"roll_speed", 30.0},
                     {"slab_nt", 8},
                     {"thickness_grading", 1.5},
                     {"heat_transfer", {{"roll_cooling", 5.0}}}};
  const Model model = rolling(2, heat);
  const MaterialData &slab = model.bodies[0].material, &roll = model.bodies[1].material;
  EXPECT_EQ(slab.conductivity, 28.0);
  EXPECT_EQ(slab.heat_capacity, kHotSteelHeatCapacity) << "hot steel's ρc unless slab_heat_capacity says otherwise";
  EXPECT_EQ(slab.temperature, 1100.0);
  EXPECT_EQ(roll.conductivity, 40.0);
  EXPECT_EQ(roll.heat_capacity, 3.6);
  EXPECT_EQ(roll.temperature, 60.0);
  ASSERT_EQ(model.contacts.size(), 1u);
  EXPECT_EQ(model.contacts[0].conductance, 20.0);
  EXPECT_EQ(model.heat.ambient, 20.0);
  std::vector<std::string> cooled;
  for (const AirCooling& a : model.heat.air) cooled.push_back(model.bodies[a.body].name + "." + a.surface);
  EXPECT_EQ(cooled, (std::vector<std::string>{"slab.ymax", "slab.xmin", "slab.xmax", "roll.outer"}))
      << "the mid-plane is a symmetry plane: adiabatic";
  // the slab's elements shrink toward its top: at the rear end (uncut), the top element is 1.5^-7 of the bottom one
  const Mesh& m = model.bodies[0].mesh;
  std::vector<double> rear;
  for (const auto& X : m.nodes)
    if (X[0] == m.nodes[0][0]) rear.push_back(X[1]);
  std::sort(rear.begin(), rear.end());
  ASSERT_EQ(rear.size(), 9u);
  EXPECT_NEAR((rear[8] - rear[7]) / (rear[1] - rear[0]), std::pow(1.5, -7), 1e-9);
  const std::string no_speed = refusal({{"type", "rolling"}, {"heat_transfer", json::object()}});
  EXPECT_NE(no_speed.find("process.roll_speed: is needed with process.heat_transfer"), std::string::npos) << no_speed;
  EXPECT_EQ(
      refusal(
          {{"type", "rolling"}, {"heat_transfer", json::object()}, {"roll_speed", 30.0}, {"slab_temperature", 1000.0}}),
      "accepted")
      << "slab_temperature is the initial temperature of the heat";
}

TEST(RollingProcess, HeatTransfersSlabThermalTableBecomesTheSlabMaterialsTable) {
  const json table = {{"temperature", {800.0, 1200.0}}, {"conductivity", {26.0, 30.0}}, {"heat_capacity", {5.2, 4.8}}};
  json heat = {{"type", "rolling"},
               {"slab_flow_stress", {{"law", "shida"}, {"carbon", 0.2}}},
               {"roll_speed", 30.0},
               {"heat_transfer", {{"slab_thermal_table", table}}}};
  const MaterialData slab = rolling(2, heat).bodies[0].material;
  EXPECT_EQ(slab.thermal_table.conductivity, (std::vector<double>{26, 30}));
  EXPECT_DOUBLE_EQ(slab.conductivity, 29) << "k at slab_temperature 1100 °C, not slab_conductivity's 28";
  EXPECT_DOUBLE_EQ(slab.heat_capacity, 4.9) << "ρc at 1100 °C: plastic work's adiabatic factor";
  EXPECT_TRUE(slab.conducts());
  heat["heat_transfer"]["slab_thermal_table"]["temperature"] = {1200.0, 800.0};
  const std::string backwards = refusal(heat);
  EXPECT_NE(backwards.find("process.heat_transfer.slab_thermal_table.temperature: must increase strictly"),
            std::string::npos)
      << backwards;
  heat["heat_transfer"]["slab_thermal_table"] = table;
  heat["slab_heat_capacity"] = 4.9;
  const std::string twice = refusal(heat);
  EXPECT_NE(twice.find("process.slab_heat_capacity: give either"), std::string::npos) << twice;
}

TEST(RollingProcess, GeometryThatCannotBeBuiltIsRefusedAtTheProcesssPath) {
  const std::string wide = refusal({{"type", "rolling"}, {"slab_width", 600.0}, {"barrel_width", 400.0}}, 3);
  EXPECT_NE(wide.find("process.slab_width: 600 mm is wider than the roll barrel (process.barrel_width: 400 mm)"),
            std::string::npos)
      << wide;
  EXPECT_EQ(refusal({{"type", "rolling"}, {"slab_width", 600.0}, {"barrel_width", 400.0}}), "accepted");  // 2D
  const std::string hub = refusal({{"type", "rolling"}, {"roll_radius", 300.0}, {"roll_hub_radius", 350.0}});
  EXPECT_NE(hub.find("process.roll_hub_radius: 350 mm must be smaller than process.roll_radius (300 mm)"),
            std::string::npos)
      << hub;
  EXPECT_EQ(hub.find("bodies["), std::string::npos) << hub;
}

// The run's progress in the pass's own terms (rollsim run's progress line): the roll's travel done, of the whole.
TEST(RollingProcess, ProgressCountsTheTravel) {
  json j = {{"dimension", 2}, {"process", {{"type", "rolling"}, {"travel", 120.0}, {"travel_increment", 1.0}}}};
  const RunConfig c = parse_project(j.dump(), "pass").config();
  EXPECT_EQ(progress_text(c, 0.0), "travel 0 of 120 mm");
  EXPECT_EQ(progress_text(c, 0.125), "travel 15 of 120 mm");
}

TEST(RollingProcess, RollDiameterInsteadOfRadiusAndASpeed) {
  // Ø 600 mm is the default R 300 mm, node for node; both at once are refused; the speed reaches the pass
  const Model by_radius = rolling(2), by_diameter = rolling(2, {{"roll_diameter", 600.0}});
  for (size_t n = 0; n < by_radius.bodies[1].mesh.nodes.size(); ++n)
    EXPECT_EQ(by_diameter.bodies[1].mesh.nodes[n], by_radius.bodies[1].mesh.nodes[n]) << n;
  EXPECT_DOUBLE_EQ(pass_of(2, {{"roll_diameter", 500.0}}).radius, 250);
  EXPECT_DOUBLE_EQ(pass_of(2, {{"roll_speed", 30.0}}).rpm, 30);
  EXPECT_DOUBLE_EQ(pass_of(2).rpm, 0);
  const std::string both = refusal({{"type", "rolling"}, {"roll_radius", 300.0}, {"roll_diameter", 600.0}});
  EXPECT_NE(both.find("process.roll_diameter: give either process.roll_radius or process.roll_diameter"),
            std::string::npos)
      << both;
  const std::string hub = refusal({{"type", "rolling"}, {"roll_diameter", 250.0}});
  EXPECT_NE(hub.find("must be smaller than half of process.roll_diameter (125 mm)"), std::string::npos) << hub;
  EXPECT_NE(refusal({{"type", "rolling"}, {"roll_speed", -5.0}}).find("process.roll_speed"), std::string::npos);
}

// A crowned roll (radius 0.5 mm smaller at 100 mm from the barrel's centre, then straight): the roll's outer nodes
// lie on R + Δr(|y|) at its axial nodes, and the slab's pre-bitten front end — at the exit plane under the roll's
// lowest point — is h1/2 − Δr thick there, on the half and on the whole width.
TEST(RollingProcess, ACrownedRollAndTheSlabCutToIt) {
  const json crown = {{{"y", 0.0}, {"radius_change", 0.0}}, {{"y", 100.0}, {"radius_change", -0.5}}};
  const auto change = [](double y) { return -0.5 * std::min(std::abs(y), 100.0) / 100.0; };
  for (const bool half : {true, false}) {
    SCOPED_TRACE(half);
    const json spec = {{"slab_nx", 4},         {"slab_nw", 4},          {"slab_nt", 2},          {"roll_n_axial", 4},
                       {"roll_n_around", 120}, {"roll_profile", crown}, {"width_symmetry", half}};
    const Model m = rolling(3, spec);
    const double R = 300, axis = 43.4 + R;
    int outer = 0;
    for (const auto& x : m.bodies[1].mesh.nodes) {
      const double r = std::hypot(x[0], x[2] - axis);
      if (r > R - 1) {
        EXPECT_NEAR(r, R + change(x[1]), 1e-9) << "y = " << x[1];
        ++outer;
      }
    }
    EXPECT_EQ(outer, 120 * (half ? 5 : 9));
    std::map<double, double> top;  // the front end's top by y: under the roll's lowest node, on the polygon
    for (const auto& x : m.bodies[0].mesh.nodes)
      if (x[0] == 0.0) top[x[1]] = std::max(top[x[1]], x[2]);
    for (const auto& [y, z] : top) EXPECT_NEAR(z, 43.4 - change(y), 1e-9) << "y = " << y;
    EXPECT_EQ(top.size(), half ? 5u : 9u);
  }
  EXPECT_EQ(pass_of(3, {{"roll_profile", crown}}).profile.at(50.0), -0.25);  // the pass carries it to its facts
}

TEST(RollingProcess, ARollProfileThatCannotBeIsRefusedAtItsPath) {
  auto refused = [](const json& profile, int dim = 3) {
    return refusal({{"type", "rolling"}, {"roll_profile", profile}}, dim);
  };
  const json crown = {{{"y", 0.0}, {"radius_change", 0.0}}, {{"y", 100.0}, {"radius_change", -0.5}}};
  EXPECT_EQ(refused(crown), "accepted");
  EXPECT_NE(refused(crown, 2).find("process.roll_profile: a roll profile varies across the width: 3D only"),
            std::string::npos);
  const json up = {{{"y", 0.0}, {"radius_change", 0.0}}, {{"y", 100.0}, {"radius_change", 0.5}}};
  EXPECT_NE(refused(up).find("process.roll_profile[1].radius_change: 0.5 mm is positive"), std::string::npos)
      << refused(up);
  const json never_zero = {{{"y", 0.0}, {"radius_change", -0.1}}};
  EXPECT_NE(refused(never_zero).find("process.roll_profile: no point has radius_change 0"), std::string::npos);
  const json outside = {{{"y", 0.0}, {"radius_change", 0.0}}, {{"y", 250.0}, {"radius_change", -0.5}}};
  EXPECT_NE(refused(outside).find("process.roll_profile[1].y: 250 mm is beyond the barrel's edge"), std::string::npos)
      << refused(outside);
  const json backwards = {{{"y", 100.0}, {"radius_change", 0.0}}, {{"y", 50.0}, {"radius_change", -0.5}}};
  EXPECT_NE(refused(backwards).find("process.roll_profile[1].y: must be greater than the point before's"),
            std::string::npos);
  const json to_hub = {{{"y", 0.0}, {"radius_change", 0.0}}, {{"y", 100.0}, {"radius_change", -160.0}}};
  EXPECT_NE(refused(to_hub).find("takes the roll's radius down to its hub"), std::string::npos) << refused(to_hub);
}

}  // namespace test_rolling_process
