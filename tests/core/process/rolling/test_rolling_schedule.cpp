// A rolling schedule (process/rolling/RollingSchedule): its checks at the user's paths, each pass's section, and two
// short passes run in process as `rollsim run` runs them — the second receives the first's measured exit
// thickness, its length with the area kept, its plastic strain and temperature profiles layer by layer, cooled in
// air over the inter-pass time.
#include <gtest/gtest.h>

#include <algorithm>

#include "../../../common/RunJson.h"
#include "process/rolling/RollingMeasures.h"
#include "process/rolling/RollingProcess.h"
#include "process/rolling/RollingSchedule.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace test_rolling_schedule {

using namespace rollsim;
using json = nlohmann::json;

namespace {
json schedule(json passes, int dim = 2) {
  return {{"name", "schedule"},
          {"dimension", dim},
          {"process",
           {{"type", "rolling"},
            {"slab_nx", 36},
            {"slab_nt", 6},
            {"slab_E", 120000.0},
            {"slab_flow_stress", {{"law", "shida"}, {"carbon", 0.2}}},
            {"roll_speed", 30.0},
            {"travel", 20.0},
            {"travel_increment", 2.0},
            {"passes", passes}}},
          {"solver", {{"mode", "direct"}}}};
}

std::string refusal(const json& j) { return testing_support::refusal_of(j); }
}  // namespace

TEST(RollingSchedule, BadSchedulesAreRefusedAtTheirPaths) {
  const auto found = [](const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
  };
  const std::string thick =
      refusal(schedule({{{"reduction", 0.2}}, {{"exit_thickness", 85.0}}}));  // pass 1 leaves 80 mm
  EXPECT_TRUE(found(thick, "process.passes[1].exit_thickness: 85 mm is not below the 80 mm the pass receives"))
      << thick;
  const std::string draft = refusal(schedule({{{"reduction", 0.2}}, {{"roll_speed", 40.0}}}));
  EXPECT_TRUE(found(draft, "process.passes[1]: give the pass either a reduction or an exit_thickness")) << draft;
  const std::string idle = refusal(schedule({{{"reduction", 0.2}}, {{"reduction", 0.2}, {"interpass_time", 5.0}}}));
  EXPECT_TRUE(found(idle, "process.passes[1].interpass_time: has no effect without process.heat_transfer")) << idle;
  const std::string negative = refusal(schedule({{{"reduction", 0.2}, {"interpass_time", -1.0}}}));
  EXPECT_TRUE(found(negative, "process.passes[0].interpass_time")) << negative;
  json both = schedule({{{"reduction", 0.2}}});
  both["process"]["reduction"] = 0.1;
  EXPECT_TRUE(found(refusal(both), "process.reduction: each pass of process.passes gives its own draft"));
  EXPECT_TRUE(found(refusal(schedule({{{"reduction", 0.2}}}, 3)), "process.passes: a schedule runs in plane strain"));
  json slow = schedule({{{"reduction", 0.2}}, {{"reduction", 0.2}, {"roll_speed", 0.0}}});
  EXPECT_TRUE(found(refusal(slow), "process.passes[1].roll_speed")) << refusal(slow);
  const std::string hub = refusal(schedule({{{"reduction", 0.2}}, {{"reduction", 0.2}, {"roll_radius", 140.0}}}));
  EXPECT_TRUE(found(hub, "process.roll_hub_radius: in pass 2 (process.passes[1]): 150 mm must be smaller")) << hub;
  EXPECT_EQ(refusal(schedule({{{"reduction", 0.2}}, {{"exit_thickness", 70.0}, {"roll_radius", 250.0}}})), "accepted");
}

TEST(RollingSchedule, APassSectionTakesThePassesSettingsInPlaceOfTheSections) {
  json p = schedule({{{"reduction", 0.2}}, {{"exit_thickness", 70.0}, {"roll_diameter", 500.0}}})["process"];
  p["roll_radius"] = 320.0;
  const json s = pass_section(p, 1);
  EXPECT_FALSE(s.contains("passes"));
  EXPECT_EQ(s.at("exit_thickness"), 70.0);
  EXPECT_FALSE(s.contains("reduction"));
  EXPECT_EQ(s.at("roll_diameter"), 500.0);
  EXPECT_FALSE(s.contains("roll_radius")) << "the pass's diameter replaces the section's radius";
  EXPECT_EQ(pass_section(p, 0).at("roll_radius"), 320.0);
}

TEST(RollingSchedule, TheNextPassReceivesTheSlabThePassBeforeLeft) {
  json j = schedule({{{"reduction", 0.2}}, {{"reduction", 0.2}, {"interpass_time", 5.0}}});
  j["process"]["slab_nt"] = 8;
  j["process"]["thickness_grading"] = 1.5;
  j["process"]["heat_transfer"] = json::object();
  j["process"]["travel"] = 110.0;  // material from before the arc (77 mm) leaves it past the exit
  j["process"]["travel_increment"] = 1.0;
  j["solver"] = {{"mode", "mixed"}, {"update", "selective"}, {"cg_tolerance", 1e-10}};  // the main job's
  const Project whole = parse_project(j.dump(), "schedule");
  ScheduleRun run(whole.data, j);
  ASSERT_EQ(run.passes(), 2u);
  EXPECT_FALSE(run.cools(0));
  const Project first = parse_project(run.pass_project(0).dump(), "pass-1");
  const Model m1 = build_model(first);
  const Results r1 = run_project(first, m1);
  ASSERT_TRUE(r1.status.ok()) << r1.status.message;
  run.finish(0, m1, r1);
  ASSERT_EQ(run.records().size(), 1u);
  const PassRecord rec = run.records()[0];
  EXPECT_NEAR(rec.exit_thickness, 80, 0.01 * 80) << "the measured exit thickness";
  const json second = run.pass_project(1);
  EXPECT_EQ(second.at("process").at("slab_thickness"), rec.exit_thickness);
  EXPECT_NEAR(second.at("process").at("slab_length").get<double>(), 300 * 100 / rec.exit_thickness, 1e-9);
  EXPECT_FALSE(second.at("process").contains("passes"));
  EXPECT_TRUE(run.cools(1));
  Model m2 = build_model(parse_project(second.dump(), "pass-2"));
  const double left = second.at("process").at("slab_temperature");
  run.cool(1, m2);
  EXPECT_FALSE(run.cools(1));
  const double cooled = run.pass_project(1).at("process").at("slab_temperature");
  EXPECT_LT(cooled, left) << "5 s in air";
  EXPECT_GT(cooled, left - 20) << "a 100 mm slab loses a few kelvin in 5 s";
  m2 = build_model(parse_project(run.pass_project(1).dump(), "pass-2"));
  run.apply(1, m2);
  const Body& slab = m2.bodies[0];
  ASSERT_EQ(slab.initial_plastic_strain.size(), static_cast<size_t>(slab.mesh.num_elements()));
  ASSERT_EQ(slab.initial_temperature.size(), static_cast<size_t>(slab.mesh.num_nodes()));
  // the rolled layers carry the pass's plastic strain, about (2/√3) ln(1.25) = 0.26 on average, more at the top
  const auto [lo, hi] = std::minmax_element(slab.initial_plastic_strain.begin(), slab.initial_plastic_strain.end());
  EXPECT_GT(*lo, 0.1);
  EXPECT_LT(*hi, 1.0);
  // the surface is colder than the core (the roll's chill, then the air)
  double top = 1e9, core = -1e9;
  for (int n = 0; n < slab.mesh.num_nodes(); ++n) {
    top = std::min(top, slab.initial_temperature[static_cast<size_t>(n)]);
    core = std::max(core, slab.initial_temperature[static_cast<size_t>(n)]);
  }
  EXPECT_LT(top, core - 10);
  const Results r2 = run_project(parse_project(run.pass_project(1).dump(), "pass-2"), m2);
  ASSERT_TRUE(r2.status.ok()) << r2.status.message;
  run.finish(1, m2, r2);
  const MeasureTable t = run.table();
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[1][t.column("interpass_time")], 5.0);
  EXPECT_NEAR(t.rows[1][t.column("entry_thickness")], rec.exit_thickness, 1e-12);
  EXPECT_NEAR(t.rows[1][t.column("entry_temperature")], cooled, 1e-9);
  EXPECT_GT(t.rows[1][t.column("roll_force")], 0.0);
  // Sims's from the strain the slab brings is harder than the virgin slab's (Shida's strain term), the same in pass 1
  EXPECT_GT(t.rows[1][t.column("sims_roll_force_carried")], 1.01 * t.rows[1][t.column("sims_roll_force")]);
  EXPECT_EQ(t.rows[0][t.column("sims_roll_force_carried")], t.rows[0][t.column("sims_roll_force")]);
  EXPECT_EQ(run.summary().at("passes").size(), 2u);
}

}  // namespace test_rolling_schedule
