// How `rollsim run` ends when it does not converge (issue: never report a failed solve as a success): the status,
// its reason and message in summary.json, the exit code (0 only for converged), the message on stderr, no result
// files; a near-singular stiffness refused naming the body; an output folder holding one run only; a pass asked
// to roll past its slab's end converged where the rear end enters the gap.
#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "../common/BentBeam.h"
#include "RunBinary.h"

namespace test_statuses {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const std::string kSamples = ROLLSIM_SOURCE_DIR "/samples/";

json sample(const std::string& name) { return json::parse(read_text(kSamples + name + ".json")); }

/// Writes `project` into a fresh folder and runs it with `extra` arguments into <folder>/out.
struct ProjectRun {
  std::string dir, out;
  RunResult result;
  json summary;
};

ProjectRun run_project(const json& project, const std::vector<std::string>& extra, const std::string& out = "") {
  ProjectRun r;
  r.dir = make_temp_dir("statuses");
  r.out = out.empty() ? r.dir + "/out" : out;
  write_text(r.dir + "/p.json", project.dump(1));
  std::vector<std::string> args{"run", r.dir + "/p.json", "--out", r.out, "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  r.result = run_rollsim(args);
  const std::string text = read_text(r.out + "/summary.json");
  if (!text.empty()) r.summary = json::parse(text);
  return r;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The coarse cantilever with Poisson's ratio `nu` and full integration.
json cantilever(double nu) {
  json j = sample("cantilever-2d-120x120");
  j["materials"][0]["nu"] = nu;
  auto& mesh = j["bodies"][0]["mesh"];
  mesh["nx"] = 40, mesh["ny"] = 10, mesh["lx"] = 40.0, mesh["ly"] = 10.0;
  j["bodies"][0]["node_sets"][0]["nearest"] = {40, 10};
  return j;
}

}  // namespace

// The reported case: a tolerance no double-precision CG can meet ended "converged" with exit 0.
TEST(RunStatuses, CgStoppedAtRoundOffAboveTheToleranceIsNotConverged) {
  const ProjectRun r = run_project(sample("block-indent-2d-50x30"), {"--solver", "mixed", "--cg-tolerance", "1e-300"});
  EXPECT_EQ(r.result.exit_code, 3) << r.result.err;
  EXPECT_EQ(r.summary.value("status", ""), "not_converged");
  EXPECT_EQ(r.summary.value("reason", ""), "round_off");
  EXPECT_TRUE(contains(r.summary.value("message", ""), "interface CG")) << r.summary.dump(1);
  EXPECT_TRUE(contains(r.summary.value("message", ""), "tolerance 1e-300")) << r.summary.dump(1);
  EXPECT_EQ(r.result.err.rfind("rollsim: not_converged: ", 0), 0u) << r.result.err;
  EXPECT_EQ(r.result.out, "");
  EXPECT_FALSE(r.summary.contains("results"));
  EXPECT_EQ(list_dir(r.out), std::vector<std::string>{"summary.json"}) << "no result.vtu of a failed solve";
  fs::remove_all(r.dir);
}

TEST(RunStatuses, ReachableCgToleranceStillConverges) {
  const ProjectRun r = run_project(sample("block-indent-2d-50x30"), {"--solver", "mixed", "--cg-tolerance", "1e-10"});
  EXPECT_EQ(r.result.exit_code, 0) << r.result.err;
  EXPECT_EQ(r.summary.value("status", ""), "converged");
  EXPECT_FALSE(r.summary.contains("reason"));
  fs::remove_all(r.dir);
}

// --interface-solver dense: the interface formed and factored takes no CG iterations, gives the CG's contact force
// and says so in summary.json; a word that is no interface solver is refused with exit 2 and names the option.
TEST(RunStatuses, DenseInterfaceSolverRunsAndIsRecorded) {
  const ProjectRun cg = run_project(sample("block-indent-2d-50x30"), {"--solver", "mixed", "--cg-tolerance", "1e-12"});
  const ProjectRun dense = run_project(sample("block-indent-2d-50x30"),
                                       {"--solver", "mixed", "--cg-tolerance", "1e-12", "--interface-solver", "dense"});
  ASSERT_EQ(dense.result.exit_code, 0) << dense.result.err;
  EXPECT_EQ(dense.summary["solver"].value("interface_solver", ""), "dense");
  EXPECT_EQ(cg.summary["solver"].value("interface_solver", ""), "krylov");
  EXPECT_EQ(dense.summary["solver"].value("cg_iterations_total", -1), 0);
  EXPECT_GT(dense.summary["solver"].value("interface_columns", 0), 0);
  const double f_cg = cg.summary["results"]["contact"]["block-base"].value("normal_force", 0.0);
  const double f_dense = dense.summary["results"]["contact"]["block-base"].value("normal_force", 0.0);
  EXPECT_GT(std::abs(f_cg), 0.0);
  EXPECT_NEAR(f_dense, f_cg, 1e-8 * std::abs(f_cg));
  const ProjectRun bad =
      run_project(sample("block-indent-2d-50x30"), {"--solver", "mixed", "--interface-solver", "lu"});
  EXPECT_EQ(bad.result.exit_code, 2);
  EXPECT_TRUE(contains(bad.result.err, "--interface-solver: must be one of krylov, dense, got \"lu\""))
      << bad.result.err;
  for (const ProjectRun* r : {&cg, &dense, &bad}) fs::remove_all(r->dir);
}

// solver.max_interface_iterations (--max-interface-iterations, a flag the schema gives it): a feti solve that needs
// more interface iterations than allowed ends not_converged (iteration_limit), exit 3; the resolved configuration in
// summary.json says what was asked.
TEST(RunStatuses, InterfaceIterationLimitIsAnOption) {
  const ProjectRun capped = run_project(sample("block-indent-dd-2d-50x30"), {"--max-interface-iterations", "3"});
  EXPECT_EQ(capped.result.exit_code, 3) << capped.result.err;
  EXPECT_EQ(capped.summary.value("reason", ""), "iteration_limit");
  EXPECT_EQ(capped.summary["config"]["solver"].value("max_interface_iterations", 0), 3);
  const ProjectRun free = run_project(sample("block-indent-dd-2d-50x30"), {});
  EXPECT_EQ(free.result.exit_code, 0) << free.result.err;
  EXPECT_EQ(free.summary["config"]["solver"].value("max_interface_iterations", 0), 10000);
  EXPECT_GT(free.summary["solver"].value("cg_iterations_total", 0), 3);
  for (const ProjectRun* r : {&capped, &free}) fs::remove_all(r->dir);
}

// The reported case: an active set still changing at its limit said "diverged" and exited 0.
TEST(RunStatuses, ActiveSetAtItsIterationLimitIsNotConvergedWithExitThree) {
  json j = sample("cylinder-indent-2d");  // its frictionless active set settles after several solves
  j["analysis"] = {{"max_active_set_iterations", 1}};
  for (const std::string solver : {"direct", "mixed"}) {
    SCOPED_TRACE(solver);
    const ProjectRun r = run_project(j, {"--solver", solver});
    EXPECT_EQ(r.result.exit_code, 3) << r.result.err;
    EXPECT_EQ(r.summary.value("status", ""), "not_converged");
    EXPECT_EQ(r.summary.value("reason", ""), "iteration_limit");
    EXPECT_TRUE(contains(r.summary.value("message", ""), "analysis.max_active_set_iterations")) << r.summary.dump(1);
    EXPECT_EQ(list_dir(r.out), std::vector<std::string>{"summary.json"});
    fs::remove_all(r.dir);
  }
  j["analysis"] = {{"max_active_set_iterations", 50}};
  const ProjectRun ok = run_project(j, {"--solver", "direct"});
  EXPECT_EQ(ok.result.exit_code, 0) << ok.result.err;
  EXPECT_GT(ok.summary["solver"].value("active_set_iterations", 0), 1) << "the case must need more than one solve";
  fs::remove_all(ok.dir);
}

// The reported case: ν = 0.5 − 1e-14 with full integration factored "successfully" (pivots of 1e-14 of their
// diagonal) and returned garbage as converged.
TEST(RunStatuses, StiffnessSingularToWorkingPrecisionIsRefusedNamingTheBody) {
  for (const std::string solver : {"direct", "skyline", "mixed"}) {
    SCOPED_TRACE(solver);
    const ProjectRun r = run_project(cantilever(0.49999999999999), {"--solver", solver});
    EXPECT_EQ(r.result.exit_code, 2) << r.result.err;
    EXPECT_EQ(r.summary.value("status", ""), "error");
    const std::string m = r.summary.value("message", "");
    EXPECT_TRUE(contains(m, "singular at body 'beam', node ")) << m;
    EXPECT_TRUE(contains(m, "of its diagonal")) << m;
    EXPECT_TRUE(contains(m, "nearly incompressible")) << m;
    EXPECT_EQ(list_dir(r.out), std::vector<std::string>{"summary.json"});
    fs::remove_all(r.dir);
  }
  const ProjectRun ok = run_project(cantilever(0.4999), {"--solver", "direct"});  // ill-conditioned, still solvable
  EXPECT_EQ(ok.result.exit_code, 0) << ok.result.err;
  fs::remove_all(ok.dir);
}

// The reported case: a failed run into a folder used before left the old result.vtu beside its error summary.
TEST(RunStatuses, OutputFolderHoldsOneRunOnly) {
  json hertz = sample("cylinder-indent-2d");
  hertz["analysis"] = {{"increments", 3}};
  const ProjectRun first = run_project(hertz, {"--solver", "direct"});
  ASSERT_EQ(first.result.exit_code, 0) << first.result.err;
  ASSERT_TRUE(fs::exists(first.out + "/results_0003.vtu"));
  write_text(first.out + "/notes.txt", "the user's own file");
  hertz["analysis"] = {{"increments", 1}};  // a converged run writing fewer files
  const ProjectRun second = run_project(hertz, {"--solver", "direct"}, first.out);
  ASSERT_EQ(second.result.exit_code, 0) << second.result.err;
  EXPECT_EQ(list_dir(first.out), (std::vector<std::string>{"notes.txt", "result.vtu", "summary.json"}));
  const ProjectRun failed =
      run_project(sample("block-indent-2d-50x30"), {"--solver", "mixed", "--cg-tolerance", "1e-300"}, first.out);
  EXPECT_EQ(failed.result.exit_code, 3) << failed.result.err;
  EXPECT_EQ(list_dir(first.out), (std::vector<std::string>{"notes.txt", "summary.json"}));
  EXPECT_EQ(failed.summary.value("status", ""), "not_converged");
  for (const ProjectRun* r : {&first, &second, &failed}) fs::remove_all(r->dir);
}

TEST(Statuses, CtrlCCancelsAndWritesWhatTheRunCompleted) {
  const std::string dir = make_temp_dir("interrupt"), out = dir + "/out";
  const RunResult r = run_program_interrupted(ROLLSIM_BINARY, {"run", kSamples + "rolling-2d-36x6.json", "--out", out},
                                              "increment 3, ", 120);
  ASSERT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 5) << r.err;  // cancelled
  EXPECT_TRUE(contains(r.err, "interrupted")) << r.err;
  const json summary = json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(summary.at("status"), "cancelled");
  // the increments that converged before the signal are kept, and the pass's measures up to there
  EXPECT_GE(summary.at("increments").size(), 2u);
  EXPECT_LT(summary.at("increments").size(), 120u);
  EXPECT_FALSE(read_text(out + "/rolling.csv").empty());
  EXPECT_FALSE(read_text(out + "/convergence.csv").empty());
}

TEST(Statuses, EachCutBackIsToldOnTheProgressLineWithItsCause) {
  // the bent beam (tests/common/BentBeam.h): each full step is cut back once and then converges, so the run ends
  // converged and only its progress lines say what happened
  const json project = testing_support::bent_beam();
  const std::string dir = make_temp_dir("cutback");
  write_text(dir + "/beam.json", project.dump(1));
  const RunResult r = run_rollsim({"run", dir + "/beam.json", "--out", dir + "/out"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "increment 1 cut back (step halved): no convergence in 4 iterations")) << r.err;
  // the progress counts the load done, which never goes back, not a total of increments that grows at each cut-back
  std::vector<double> done;
  const std::string tag = ", load factor ";
  for (size_t at = r.err.find(tag); at != std::string::npos; at = r.err.find(tag, at + 1))
    done.push_back(std::stod(r.err.substr(at + tag.size())));
  ASSERT_GE(done.size(), 3u) << r.err;
  EXPECT_EQ(done.front(), 0.0);
  for (size_t i = 1; i < done.size(); ++i) EXPECT_GE(done[i], done[i - 1]) << r.err;
  fs::remove_all(dir);
}

TEST(Statuses, APassLongerThanItsSlabEndsConvergedWhenTheRearEndEntersTheGap) {
  // issue 38: 500 mm of travel on a 300 mm slab computed 333 increments, then ended `error` ("the system is
  // singular … add a support") with no increment kept. A 100 mm slab asked for 100 mm of travel: the rear end (at
  // x = −100) reaches the entry of the arc (−√(R Δh) = −62.9 mm) after about 37 · h0/h1 ≈ 43 mm
  json p = sample("rolling-2d-36x6");
  p["process"]["slab_length"] = 100;
  p["process"]["slab_nx"] = 12;
  p["process"]["travel"] = 100;
  p["process"]["travel_increment"] = 2;
  const ProjectRun r = run_project(p, {});
  ASSERT_EQ(r.result.exit_code, 0) << r.result.err;
  EXPECT_EQ(r.summary["status"], "converged");
  const std::string why = r.summary.value("message", "");
  EXPECT_NE(why.find("the slab's rear end has entered the roll gap"), std::string::npos) << why;
  EXPECT_NE(why.find("process.travel asked for 100 mm"), std::string::npos) << why;
  const json& incs = r.summary["increments"];
  ASSERT_FALSE(incs.empty());
  const double travel = incs.back()["travel"];
  EXPECT_GT(travel, 30.0);
  EXPECT_LT(travel, 60.0);
  EXPECT_TRUE(fs::exists(r.out + "/result.vtu"));
  EXPECT_TRUE(fs::exists(r.out + "/rolling.csv"));
}

}  // namespace test_statuses
