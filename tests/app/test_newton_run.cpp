// `rollsim run` on a plastic project: the Newton analysis is chosen by the material, writes convergence.csv and the
// plastic strain field, ends `diverged` with exit code 4 and the increment named when no equilibrium exists, and
// refuses bad plasticity input with exit 2 and the JSON path; a rolling pass prints its measures and writes its tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include <nlohmann/json.hpp>

#include "../common/RollingPass.h"
#include "RunBinary.h"

namespace test_newton_run {

using json = nlohmann::json;

namespace {
json plastic_block() {
  return {{"name", "plastic-block"},
          {"dimension", 2},
          {"materials",
           {{{"name", "steel"}, {"E", 200e3}, {"nu", 0.3}, {"yield_stress", 250.0}, {"hardening_modulus", 2000.0}}}},
          {"bodies",
           {{{"name", "block"},
             {"material", "steel"},
             {"formulation", "bbar"},
             {"mesh", {{"type", "block"}, {"nx", 6}, {"ny", 6}, {"lx", 10.0}, {"ly", 10.0}}}}}},
          {"boundary_conditions",
           {{{"type", "displacement"}, {"body", "block"}, {"set", "ymin"}, {"uy", 0.0}},
            {{"type", "displacement"}, {"body", "block"}, {"set", "xmin"}, {"ux", 0.0}},
            {{"type", "displacement"}, {"body", "block"}, {"set", "ymax"}, {"uy", -0.2}}}},
          {"analysis", {{"increments", 4}}}};
}

struct NewtonOutcome {
  std::string out;
  RunResult result;
  json summary;
};

NewtonOutcome run(const json& project, std::vector<std::string> extra = {}) {
  NewtonOutcome r;
  const std::string dir = make_temp_dir("newton");
  r.out = dir + "/out";
  write_text(dir + "/p.json", project.dump(1));
  std::vector<std::string> args{"run", dir + "/p.json", "--out", r.out, "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  r.result = run_rollsim(args);
  const std::string text = read_text(r.out + "/summary.json");
  if (!text.empty()) r.summary = json::parse(text);
  return r;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
size_t count(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}
}  // namespace

TEST(NewtonRun, PlasticProjectRunsNewtonAndWritesItsOutputs) {
  const NewtonOutcome r = run(plastic_block(), {"--update", "selective"});
  ASSERT_EQ(r.result.exit_code, 0) << r.result.err;
  EXPECT_EQ(r.summary["analysis"], "newton");
  EXPECT_EQ(r.summary["solver"]["update"], "selective:0.01");
  EXPECT_GT(r.summary["results"]["max_plastic_strain"]["block"].get<double>(), 0.01);
  ASSERT_EQ(r.summary["increments"].size(), 4u);
  EXPECT_GE(r.summary["increments"][0]["newton_iterations"].get<int>(), 2);
  const std::string csv = read_text(r.out + "/convergence.csv");
  EXPECT_TRUE(contains(csv, "increment,attempt,iteration,load_factor,residual")) << csv;
  EXPECT_GE(std::count(csv.begin(), csv.end(), '\n'), 9);
  EXPECT_TRUE(contains(read_text(r.out + "/result.vtu"), "Name=\"plastic_strain\""));
}

TEST(NewtonRun, NoEquilibriumIsDivergedWithExitCode4) {
  json p = plastic_block();
  p["materials"][0]["hardening_modulus"] = 0.0;
  p["boundary_conditions"][2] = {{"type", "pressure"}, {"body", "block"}, {"surface", "ymax"}, {"value", 400.0}};
  p["analysis"]["max_cutbacks"] = 2;
  const NewtonOutcome r = run(p);
  EXPECT_EQ(r.result.exit_code, 4) << r.result.err;
  EXPECT_EQ(r.summary["status"], "diverged");
  EXPECT_TRUE(contains(r.result.err, "diverged: increment")) << r.result.err;
  EXPECT_TRUE(contains(r.summary["message"].get<std::string>(), "2 cut-backs"));
  EXPECT_FALSE(read_text(r.out + "/convergence.csv").empty());
  EXPECT_TRUE(read_text(r.out + "/result.vtu").empty()) << "no result of a run that failed";
  // what it computed before the failure is kept: the last converged increment's fields, the load factor with them
  ASSERT_FALSE(r.summary["increments"].empty()) << "the case must converge an increment before it diverges";
  const std::string last = read_text(r.out + "/last_converged.vtu");
  EXPECT_TRUE(contains(last, "Name=\"load_factor\"")) << last.substr(0, 2000);
  if (r.summary["increments"].size() > 1) {  // and every converged increment, for ParaView to step through
    EXPECT_EQ(count(read_text(r.out + "/results.pvd"), "<DataSet "), r.summary["increments"].size());
  }
}

TEST(NewtonRun, BadPlasticityInputIsRefusedWithItsPath) {
  struct Case {
    std::string what, path;
    std::function<void(json&)> edit;
    std::vector<std::string> extra;
  };
  const std::vector<Case> cases = {
      {"yield stress not positive",
       "materials[0].yield_stress",
       [](json& p) { p["materials"][0]["yield_stress"] = 0.0; },
       {}},
      {"negative hardening",
       "materials[0].hardening_modulus",
       [](json& p) { p["materials"][0]["hardening_modulus"] = -10.0; },
       {}},
      {"saturation below yield",
       "materials[0].saturation_stress",
       [](json& p) { p["materials"][0]["saturation_stress"] = 100.0; },
       {}},
      {"j2 without yield stress",
       "materials[0].yield_stress",
       [](json& p) {
         p["materials"][0].erase("yield_stress");
         p["materials"][0]["model"] = "j2_plasticity";
       },
       {}},
      {"linear analysis of a plastic body", "analysis.type", [](json& p) { p["analysis"]["type"] = "linear"; }, {}},
      {"zero increments", "analysis.increments", [](json& p) { p["analysis"]["increments"] = 0; }, {}},
      {"unknown policy in the project", "solver.update", [](json& p) { p["solver"]["update"] = "selective:2"; }, {}},
      {"unknown policy on the command line", "--update", [](json&) {}, {"--update", "sometimes"}},
      {"rotation without an axis in 3D",
       "boundary_conditions[3].axis",
       [](json& p) {
         p["dimension"] = 3;
         p["bodies"][0]["mesh"].update({{"nz", 2}, {"lz", 4.0}});
         p["boundary_conditions"].push_back(
             {{"type", "rotation"}, {"body", "block"}, {"set", "xmax"}, {"center", {0, 0, 0}}, {"angle", 5.0}});
       },
       {}},
      {"rotation axis given in 2D",
       "boundary_conditions[3].axis",
       [](json& p) {
         p["boundary_conditions"].push_back({{"type", "rotation"},
                                             {"body", "block"},
                                             {"set", "xmax"},
                                             {"center", {0, 0}},
                                             {"axis", {0, 0, 1}},
                                             {"angle", 5.0}});
       },
       {}},
      {"rotation without its angle",
       "boundary_conditions[3].angle",
       [](json& p) {
         p["boundary_conditions"].push_back(
             {{"type", "rotation"}, {"body", "block"}, {"set", "xmax"}, {"center", {0, 0}}});
       },
       {}},
      {"rotation and a displacement on one node",
       "boundary_conditions[3]",
       [](json& p) {
         p["boundary_conditions"].push_back(
             {{"type", "rotation"}, {"body", "block"}, {"set", "ymax"}, {"center", {0, 0}}, {"angle", 5.0}});
       },
       {}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    json p = plastic_block();
    c.edit(p);
    const NewtonOutcome r = run(p, c.extra);
    EXPECT_EQ(r.result.exit_code, 2) << r.result.err;
    EXPECT_TRUE(contains(r.result.err, c.path)) << r.result.err;
    EXPECT_TRUE(r.summary.is_null()) << "nothing written for invalid input";
  }
}

TEST(NewtonRun, RollingPassThatCannotBiteExitsSix) {
  json pass = testing_support::paper_pass_2d(1.0, 1.0);
  pass["process"]["friction"] = "coulomb";
  pass["process"]["friction_coefficient"] = 0.15;
  const std::string dir = make_temp_dir("nobite");
  write_text(dir + "/p.json", pass.dump(1));
  const auto result = run_rollsim({"run", dir + "/p.json", "--out", dir + "/out"});
  EXPECT_EQ(result.exit_code, 6) << result.err;
  EXPECT_TRUE(contains(result.err, "rollsim: no_bite: the roll cannot draw the slab in")) << result.err;
  const json summary = json::parse(read_text(dir + "/out/summary.json"));
  EXPECT_EQ(summary["status"], "no_bite");
  // `check` runs every test that needs no solve: it finds the same refusal, with the same exit code
  const auto checked = run_rollsim({"check", dir + "/p.json"});
  EXPECT_EQ(checked.exit_code, 6) << checked.out << checked.err;
  EXPECT_TRUE(contains(checked.err, "rollsim: no_bite: the roll cannot draw the slab in")) << checked.err;
  EXPECT_FALSE(contains(checked.out, "valid")) << checked.out;
}

TEST(NewtonRun, RollingPassPrintsItsMeasuresAndWritesItsTables) {
  // the first 2 mm of the paper's plane-strain pass (coarse): roll force, torque and forward slip on stderr, the
  // increments in rolling.csv, the arc in contact_profile.csv, results.rolling with its units in summary.json
  const json pass = testing_support::paper_pass_2d(2.0, 1.0);
  NewtonOutcome r;
  const std::string dir = make_temp_dir("rolling");
  r.out = dir + "/out";
  write_text(dir + "/p.json", pass.dump(1));
  r.result = run_rollsim({"run", dir + "/p.json", "--out", r.out});
  ASSERT_EQ(r.result.exit_code, 0) << r.result.err;
  EXPECT_TRUE(contains(r.result.err, "rollsim: rolling: roll force ")) << r.result.err;
  EXPECT_TRUE(contains(r.result.err, "N/mm, torque ")) << r.result.err;
  EXPECT_TRUE(contains(r.result.err, "last completed increment, 2 mm of travel: not steady yet")) << r.result.err;
  const json summary = json::parse(read_text(r.out + "/summary.json"));
  const json& rolling = summary["results"]["rolling"];
  EXPECT_GT(rolling["roll_force"].get<double>(), 4000.0);
  EXPECT_EQ(rolling["units"]["roll_force"], "N/mm (per unit width)");
  EXPECT_EQ(rolling["bite_increment"], 1);
  // the closed forms beside (process/rolling/RollingTheory): Sims's 6.78 MN/m and 213 kN·m/m, printed and in the
  // summary
  EXPECT_TRUE(contains(r.result.err,
                       "Sims (sticking friction): roll force 6781 N/mm, torque 2.127e+05 N·mm/mm, forward slip 2.47 %"))
      << r.result.err;
  EXPECT_NEAR(rolling["theory"]["sims_roll_force"].get<double>(), 6781, 1);
  EXPECT_NEAR(rolling["theory"]["bite_angle"].get<double>(), 12.04, 0.01);
  const std::string table = read_text(r.out + "/rolling.csv");
  EXPECT_TRUE(contains(table, "increment,travel,roll_force,roll_torque,contact_length,exit_thickness")) << table;
  EXPECT_GE(std::count(table.begin(), table.end(), '\n'), 3);
  const std::string arc = read_text(r.out + "/contact_profile.csv");
  EXPECT_TRUE(contains(arc, "angle,x,width,pressure,shear")) << arc;
  EXPECT_GE(std::count(arc.begin(), arc.end(), '\n'), 6);
  // the two plots, drawn by the chart sink every build has (cairo, no display, no window): PNG files with axes,
  // lines and text
  for (const char* png : {"/rolling.png", "/contact_profile.png"}) {
    const std::string bytes = read_text(r.out + png);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << png;
    EXPECT_GT(bytes.size(), 10000u) << png;
  }
}

}  // namespace test_newton_run
