// The first millimetres of the paper's plane-strain pass (100 → 86.8 mm, R 300 mm, σ_0 100 MPa, E 210 GPa, sticking
// friction without slip, coarse 36 × 6 slab): the roll bites at once (pre-bitten entry), and its measures are those of
// a pass — roll force within the slab method's range, the lever arm of the torque a fraction of the contact length,
// the contact length and exit thickness those of the nominal geometry, the slab leaving faster than the roll — and
// its pressure along the arc carries the roll force, its friction within the slab's shear yield stress k.
#include <gtest/gtest.h>

#include <cmath>

#include "../../../common/PassRun.h"
#include "../../../common/RollingPass.h"

namespace test_rolling_pass {

using namespace rollsim;

TEST(RollingPass, FirstMillimetresMeasureLikeAPass) {
  const testing_support::PassRun r = testing_support::run_pass(testing_support::paper_pass_2d(4.0, 2.0));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.rolling && r.process);
  const RollingResults& roll = *r.rolling;
  // the process's generic table (rolling.csv) holds the same measures, under their registered names
  const MeasureTable* table = r.process->table("rolling");
  ASSERT_TRUE(table);
  ASSERT_EQ(table->rows.size(), roll.increments.size());
  EXPECT_EQ(table->rows.back()[table->column("roll_force")], roll.increments.back().roll_force);
  EXPECT_EQ(table->columns[table->column("roll_force")].unit, "N/mm (per unit width)");
  EXPECT_FALSE(roll.thermal) << "σ_0 and no heat: no temperature, no temperature columns";
  EXPECT_EQ(table->columns.size(), 12u);
  ASSERT_GE(roll.increments.size(), 2u);  // 2 mm steps, more where the driver cut one back
  EXPECT_EQ(roll.bite_increment, 1);
  const RollingIncrement& last = roll.increments.back();
  EXPECT_DOUBLE_EQ(last.travel, 4.0);
  // Sims 6.78 MN/m and the homogeneous slab with sticking friction 8.23 MN/m (docs: the pass is not steady yet)
  EXPECT_GT(last.roll_force, 0.7 * 6780);
  EXPECT_LT(last.roll_force, 1.3 * 8230);
  const double L = std::sqrt(300 * 13.2);  // nominal projected contact length √(R Δh)
  EXPECT_GT(last.roll_torque / last.roll_force, 0.3 * L);
  EXPECT_LT(last.roll_torque / last.roll_force, 0.8 * L);
  EXPECT_NEAR(last.contact_length, L, 0.1 * L);
  EXPECT_NEAR(last.exit_thickness, 86.8, 0.005 * 86.8);
  EXPECT_GT(last.forward_slip, 0.0);
  EXPECT_LT(last.forward_slip, 0.15);
  EXPECT_EQ(last.spread, 0.0);  // plane strain
  // the mean pressure on the arc, F / L: about the plane-strain flow stress 2k = 115 MPa times Sims's Q_p
  EXPECT_DOUBLE_EQ(last.mean_pressure, last.roll_force / last.contact_length);
  EXPECT_GT(last.mean_pressure, 100.0);
  EXPECT_LT(last.mean_pressure, 150.0);
  EXPECT_EQ(table->columns[table->column("mean_pressure")].unit, "MPa");
  // the arc: every contact node of the last increment, entry first, pressed, its friction within k = σ_0/√3; the
  // pressure integrated along x (each node's share: half-way to its neighbours) carries the roll force
  const std::vector<ArcPoint>& arc = roll.profile;
  ASSERT_GE(arc.size(), 5u);
  double integral = 0;
  for (size_t i = 0; i < arc.size(); ++i) {
    EXPECT_GT(arc[i].pressure, 0.0);
    EXPECT_LE(std::abs(arc[i].shear), 100 / std::sqrt(3.0) * (1 + 1e-6)) << i;
    if (i > 0) EXPECT_LT(arc[i].angle, arc[i - 1].angle);
    const double left = i > 0 ? (arc[i].x - arc[i - 1].x) / 2 : (arc[1].x - arc[0].x) / 2;
    const double right = i + 1 < arc.size() ? (arc[i + 1].x - arc[i].x) / 2 : (arc[i].x - arc[i - 1].x) / 2;
    integral += arc[i].pressure * (left + right);
  }
  EXPECT_NEAR(integral, last.roll_force, 0.1 * last.roll_force);
  EXPECT_GT(arc.front().angle, 8.0);  // from near the entry (bite angle 12°)…
  EXPECT_LT(arc.back().angle, 2.0);   // …to near the exit
}

// A pass with heat (process.heat_transfer): the roll chills the slab's surface under the arc and warms; the slab's
// interior keeps its temperature over a few millimetres; rolling.csv has the temperature columns (a pass without a
// temperature has none: FirstMillimetresMeasureLikeAPass).
TEST(RollingPass, AHotPassWithHeatChillsTheSlabsSurfaceAndWarmsTheRoll) {
  nlohmann::json hot = testing_support::paper_pass_2d(6.0, 1.0);
  hot["process"].update({{"slab_flow_stress", {{"law", "shida"}, {"carbon", 0.2}}},
                         {"slab_E", 120000.0},
                         {"roll_speed", 30.0},
                         {"slab_nt", 8},
                         {"thickness_grading", 1.5}});
  nlohmann::json heat = hot;
  heat["process"]["heat_transfer"] = nlohmann::json::object();
  const testing_support::PassRun r = testing_support::run_pass(heat), cold = testing_support::run_pass(hot);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(cold.status.ok()) << cold.status.message;
  ASSERT_TRUE(r.rolling && r.rolling->thermal);
  const RollingIncrement& last = r.rolling->increments.back();
  EXPECT_LT(last.surface_temperature, 1100 - 20) << "tens of kelvin of chill in the top millimetre";
  EXPECT_GT(last.surface_temperature, 900.0);
  EXPECT_GT(last.roll_temperature, 60.5) << "the roll's surface warms";
  EXPECT_NEAR(last.slab_temperature, 1100, 2.0) << "the slab's mean barely moves in 6 mm";
  const MeasureTable* table = r.process->table("rolling");
  ASSERT_TRUE(table);
  EXPECT_EQ(table->columns[table->column("surface_temperature")].unit, "°C");
  EXPECT_TRUE(cold.rolling->thermal) << "a flow stress law gives the slab a temperature, constant here";
  EXPECT_EQ(cold.rolling->increments.back().surface_temperature, 1100.0);
  // 6 mm in, the chilled layer is thin: the force moves by a fraction of a per cent (plastic heat softens, the chill
  // hardens)
  EXPECT_NEAR(last.roll_force, cold.rolling->increments.back().roll_force,
              0.01 * cold.rolling->increments.back().roll_force);
  // the roll conducts: its nodal temperatures, an output at its nodes
  EXPECT_EQ(r.bodies[1].nodal_temperature.size(), static_cast<Eigen::Index>(r.bodies[1].displacement.size() / 2));
  EXPECT_GT(r.bodies[1].nodal_temperature.maxCoeff(), 60.5);
}

// A rigid roll (process.roll: rigid) is moved wholly by its rotation: it has no group, so nothing of it is assembled
// or factored, and its force comes from the contact on its driven nodes (their reactions include the contact
// force). Over the same first 2 mm it carries the slab's contact force, and measures the pass like the elastic roll.
TEST(RollingPass, RigidRollIsDrivenWithoutFactoringAndCarriesTheContactForce) {
  nlohmann::json rigid = testing_support::paper_pass_2d(2.0, 1.0);
  rigid["process"]["roll"] = "rigid";
  const testing_support::PassRun r = testing_support::run_pass(rigid);
  const testing_support::PassRun e = testing_support::run_pass(testing_support::paper_pass_2d(2.0, 1.0));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  EXPECT_EQ(r.solver.factorizations.count("roll"), 0u);
  EXPECT_GT(r.solver.factorizations.at("slab"), 0);
  EXPECT_GT(e.solver.factorizations.at("roll"), 0);
  const RollingIncrement &rigid_last = r.rolling->increments.back(), &elastic_last = e.rolling->increments.back();
  ASSERT_EQ(r.contacts.size(), 1u);
  // the arc spans 12°: the normal force's thickness component is 0.98–1 of it
  EXPECT_GT(rigid_last.roll_force, 0.97 * r.contacts[0].normal_force);
  EXPECT_LT(rigid_last.roll_force, 1.01 * r.contacts[0].normal_force);
  EXPECT_GT(rigid_last.roll_torque, 0.0);
  // on this coarse slab a node more or less at the entry (the roll's flattening) moves the force by about a tenth
  EXPECT_NEAR(rigid_last.roll_force, elastic_last.roll_force, 0.15 * elastic_last.roll_force);
  EXPECT_NEAR(rigid_last.roll_torque / rigid_last.roll_force, elastic_last.roll_torque / elastic_last.roll_force,
              0.15 * elastic_last.roll_torque / elastic_last.roll_force);
  EXPECT_NEAR(rigid_last.exit_thickness, 86.8, 0.005 * 86.8);
}

// A fixed roll (process.roll_mesh: fixed) stays where it is meshed while its surface's material turns: linear, it is
// assembled and factored once under the selective update (again only after a cut-back), where the turning roll is
// factored at most steps.
// Its contact holds the slab to its circle, not its facets' chords: on a coarse roll of 60 facets (31 mm long, their
// sagitta 0.41 mm) its force over 20–30 mm of travel is a fine turning roll's (240 facets) within 0.2 %, where the
// coarse turning roll's is 2 % below it.
TEST(RollingPass, AFixedRollIsFactoredOnceAndTheSlabMeetsItsCircle) {
  auto run = [](const std::string& mesh, int around) {
    nlohmann::json j = testing_support::paper_pass_2d(30.0, 1.0);
    j["process"].update({{"roll_mesh", mesh}, {"roll_n_around", around}});
    j["solver"] = {{"mode", "mixed"}, {"update", "selective"}, {"cg_tolerance", 1e-10}};
    const testing_support::PassRun r = testing_support::run_pass(j);
    EXPECT_TRUE(r.status.ok()) << mesh << " " << around << ": " << r.status.message;
    double sum = 0;
    int n = 0;
    for (const RollingIncrement& i : r.rolling->increments)
      if (i.travel >= 20) sum += i.roll_force, ++n;
    return std::pair{sum / n, r.solver.factorizations.at("roll")};
  };
  const auto [fixed, fixed_factors] = run("fixed", 60);
  const auto [coarse, coarse_factors] = run("turning", 60);
  const auto [fine, fine_factors] = run("turning", 240);
  EXPECT_LE(fixed_factors, 2);
  EXPECT_GE(coarse_factors, 20);
  EXPECT_NEAR(fixed, fine, 0.002 * fine);
  EXPECT_LT(coarse, 0.99 * fine) << "the coarse turning roll's chords";
}

// A pass whose friction cannot draw the slab in is answered `no_bite` before anything is solved, with the numbers:
// the paper's draft (13.2 mm on R 300 mm) has a bite angle of 12.04°, tan α = 0.213; μ = 0.1 bites at most 2.98 mm.
// Frictionless cannot bite at all; μ = 0.3 and sticking friction bite.
TEST(RollingPass, FrictionBelowTheBiteAngleIsNoBite) {
  nlohmann::json low = testing_support::paper_pass_2d(1.0, 1.0);
  low["process"]["friction"] = "coulomb";
  low["process"]["friction_coefficient"] = 0.1;
  const testing_support::PassRun r = testing_support::run_pass(low);
  EXPECT_EQ(r.status.status, Status::no_bite);
  EXPECT_NE(r.status.message.find("0.1 is below tan α = 0.213"), std::string::npos) << r.status.message;
  EXPECT_NE(r.status.message.find("α = 12.04°"), std::string::npos) << r.status.message;
  EXPECT_NE(r.status.message.find("at most 2.98 mm"), std::string::npos) << r.status.message;
  EXPECT_TRUE(r.increments.empty());
  nlohmann::json frictionless = low;
  frictionless["process"]["friction"] = "frictionless";
  frictionless["process"].erase("friction_coefficient");
  EXPECT_EQ(testing_support::run_pass(frictionless).status.status, Status::no_bite);
  nlohmann::json enough = low;
  enough["process"]["friction_coefficient"] = 0.3;
  const testing_support::PassRun bites = testing_support::run_pass(enough);
  EXPECT_TRUE(bites.status.ok()) << bites.status.message;
  EXPECT_EQ(bites.rolling->bite_increment, 1);
}

// The same pass gives the same roll force and torque whichever way its linear systems are solved: one global matrix
// (direct), each body factored on its own with CG on the contact interface (mixed), or the slab torn into subdomains
// along its length with the roll one more (feti) — all with the selective update, which keeps the same tangents in
// each (the paper's Mixed II / DD-II), and a tight interface CG — or the interface formed and factored (`dense`).
TEST(RollingPass, EverySolverModeGivesTheSameRollForce) {
  nlohmann::json pass = testing_support::paper_pass_2d(3.0, 1.0);
  pass["solver"] = {{"mode", "direct"}, {"update", "selective"}, {"cg_tolerance", 1e-12}};
  const testing_support::PassRun direct = testing_support::run_pass(pass);
  ASSERT_TRUE(direct.status.ok()) << direct.status.message;
  const RollingIncrement& ref = direct.rolling->increments.back();
  pass["solver"]["mode"] = "mixed";
  const testing_support::PassRun mixed = testing_support::run_pass(pass);
  pass["solver"]["interface_solver"] = "dense";
  const testing_support::PassRun mixed_dense = testing_support::run_pass(pass);
  pass["solver"]["mode"] = "feti";
  pass["process"]["slab_partition"] = "3x1";
  const testing_support::PassRun feti_dense = testing_support::run_pass(pass);
  pass["solver"]["interface_solver"] = "krylov";
  const testing_support::PassRun feti = testing_support::run_pass(pass);
  for (const testing_support::PassRun* r : {&mixed, &mixed_dense, &feti, &feti_dense}) {
    ASSERT_TRUE(r->status.ok()) << r->status.message;
    const RollingIncrement& last = r->rolling->increments.back();
    EXPECT_EQ(last.travel, ref.travel);
    EXPECT_NEAR(last.roll_force, ref.roll_force, 1e-6 * ref.roll_force);
    EXPECT_NEAR(last.roll_torque, ref.roll_torque, 1e-6 * ref.roll_torque);
  }
}

// process.width_symmetry: the whole width (false) and the half width with its symmetry planes (the default) are the
// same pass: a coarse 3D pass over its first 2 mm gives the same roll force, torque, contact area and spread from
// both, the whole-width model counting its force once and the half-width model twice — with a rigid roll, and with an
// elastic one, whose barrel centre plane the half model holds as it holds the slab's (left free, the half pass was
// 2.4e-5 off the whole one in force, with a cut-back the whole one did not need, and in 0.125 mm steps it inverted
// an element). (The forward slip is not compared: it is the plain mean advance of the front face's nodes, whose
// weights differ between the two.)
class WidthSymmetry : public ::testing::TestWithParam<std::string> {};

TEST_P(WidthSymmetry, WholeWidthGivesTheHalfWidthPass) {
  const bool rigid = GetParam() == "rigid";
  nlohmann::json half = {{"name", "pass3d"},
                         {"dimension", 3},
                         {"process",
                          {{"type", "rolling"},
                           {"slab_nx", 16},
                           {"slab_nw", 2},
                           {"slab_nt", 2},
                           {"roll", GetParam()},
                           {"roll_n_around", 48},
                           {"roll_n_radial", 2},
                           {"roll_n_axial", 2},
                           {"travel", 2.0},
                           {"travel_increment", rigid ? 1.0 : 0.25}}},
                         {"solver", {{"mode", "mixed"}, {"cg_tolerance", 1e-10}}}};
  nlohmann::json whole = half;
  whole["process"]["width_symmetry"] = false;
  const testing_support::PassRun h = testing_support::run_pass(half), w = testing_support::run_pass(whole);
  ASSERT_TRUE(h.status.ok()) << h.status.message;
  ASSERT_TRUE(w.status.ok()) << w.status.message;
  ASSERT_TRUE(h.rolling && w.rolling);
  ASSERT_EQ(h.increments.size(), w.increments.size());
  const RollingIncrement &a = h.rolling->increments.back(), &b = w.rolling->increments.back();
  EXPECT_GT(a.roll_force, 0.0);
  EXPECT_NEAR(b.roll_force, a.roll_force, 1e-6 * a.roll_force);
  EXPECT_NEAR(b.roll_torque, a.roll_torque, 1e-6 * std::abs(a.roll_torque));
  EXPECT_NEAR(b.contact_length, a.contact_length, 1e-6 * a.contact_length);
  EXPECT_NEAR(b.spread, a.spread, 1e-6 * 350);
}

INSTANTIATE_TEST_SUITE_P(Roll, WidthSymmetry, ::testing::Values("rigid", "elastic"));

// Coulomb friction in 3D (μ 0.3): a coarse pass (rigid roll) rolls its first 3 mm in 0.5 mm steps without a cut-back,
// with a roll force and forward slip a little below the sticking pass's (friction that may slip holds less). A
// friction direction taken from each point's slip alone threw the points that slip next to nothing to and fro: the
// same pass diverged at 1 mm (contact/Friction.h, the trial force's direction).
TEST(RollingPass, A3DPassWithCoulombFrictionRollsBelowTheStickingPass) {
  nlohmann::json sticking = {{"name", "coulomb3d"},
                             {"dimension", 3},
                             {"process",
                              {{"type", "rolling"},
                               {"slab_nx", 16},
                               {"slab_nw", 4},
                               {"slab_nt", 2},
                               {"roll", "rigid"},
                               {"roll_n_around", 48},
                               {"roll_n_axial", 2},
                               {"travel", 3.0},
                               {"travel_increment", 0.5}}}};
  nlohmann::json coulomb = sticking;
  coulomb["process"]["friction"] = "coulomb";
  const testing_support::PassRun s = testing_support::run_pass(sticking), c = testing_support::run_pass(coulomb);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  ASSERT_EQ(c.increments.size(), 6u);
  for (const IncrementResults& inc : c.increments) EXPECT_EQ(inc.cutbacks, 0);
  const RollingIncrement &a = s.rolling->increments.back(), &b = c.rolling->increments.back();
  EXPECT_LT(b.roll_force, a.roll_force);
  EXPECT_GT(b.roll_force, 0.97 * a.roll_force);
  EXPECT_LT(b.forward_slip, a.forward_slip);
  EXPECT_GT(b.forward_slip, 0.5 * a.forward_slip);
}

}  // namespace test_rolling_pass
