// Tests of summary.json's factorization rate: factor_gflops = all factorizations' flops (factor_flops_total, beside
// it) over their seconds, and its
// fraction of the DGEMM peak when the run measured one; nothing of the kind when nothing was factored. Every
// increment lists its probes' displacements and reactions (a load–displacement curve), and a probe on a body that
// conducts heat its temperature.
#include <gtest/gtest.h>

#include "io/Summary.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace rollsim::test_summary {
namespace {

Results factored(double flops, double seconds) {
  Results r;
  r.status = {Status::error, Reason::none, "no fields needed here"};  // the solver section without results
  r.solver.factor_flops_total = flops;
  r.timing.factorize_s = seconds;
  return r;
}

TEST(Summary, ReportsTheFactorizationRateAgainstThePeak) {
  RunInfo run{"t", "direct"};
  run.dgemm_peak_gflops = 40;
  run.peak_probe_s = 0.01;
  const auto s = make_summary(Model{}, factored(6e9, 0.5), run);
  EXPECT_DOUBLE_EQ(s["solver"]["factor_gflops"].get<double>(), 12.0);
  // the flops the rate is taken from, beside it: a mode that factors groups apart has no global factor_flops
  EXPECT_DOUBLE_EQ(s["solver"]["factor_flops_total"].get<double>(), 6e9);
  EXPECT_DOUBLE_EQ(s["solver"]["dgemm_peak_gflops"].get<double>(), 40.0);
  EXPECT_DOUBLE_EQ(s["solver"]["factor_peak_fraction"].get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(s["timing"]["peak_probe_s"].get<double>(), 0.01);
}

TEST(Summary, LeavesThePeakOutWhenNotMeasuredAndTheRateWhenNothingWasFactored) {
  const auto s = make_summary(Model{}, factored(6e9, 0.5), RunInfo{"t", "direct"});
  EXPECT_DOUBLE_EQ(s["solver"]["factor_gflops"].get<double>(), 12.0);
  EXPECT_FALSE(s["solver"].contains("factor_peak_fraction"));
  EXPECT_FALSE(s["timing"].contains("peak_probe_s"));
  const auto none = make_summary(Model{}, factored(0, 0), RunInfo{"t", "petsc"});
  EXPECT_FALSE(none["solver"].contains("factor_gflops"));
}

TEST(Summary, ListsEveryIncrementsProbesAndReactions) {
  const json j = {{"dimension", 2},
                  {"materials", {{{"name", "m"}, {"E", 1000.0}, {"nu", 0.3}}}},
                  {"bodies",
                   {{{"name", "b"},
                     {"material", "m"},
                     {"mesh", {{"type", "block"}, {"nx", 4}, {"ny", 2}, {"lx", 4.0}, {"ly", 2.0}}}}}},
                  {"boundary_conditions",
                   {{{"type", "displacement"}, {"body", "b"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}},
                    {{"type", "displacement"}, {"body", "b"}, {"set", "xmax"}, {"ux", 0.4}}}},
                  {"analysis", {{"increments", 4}}},
                  {"probes", {{{"name", "tip"}, {"at", {4.0, 2.0}}}}}};
  const Project p = parse_project(j.dump(), "curve.json");
  const Model m = build_model(p);
  const auto s = make_summary(m, run_project(p, m), RunInfo{"curve", "direct"});
  ASSERT_EQ(s["increments"].size(), 4u);
  const json& last = s["increments"][3];
  EXPECT_EQ(last["probes"]["tip"], s["results"]["probes"]["tip"]["displacement"]);
  EXPECT_EQ(last["reactions"], s["results"]["reactions"]);
  // linear: the first increment is a quarter of the last
  const double f1 = s["increments"][0]["reactions"]["b"]["xmax"][0].get<double>();
  const double f4 = last["reactions"]["b"]["xmax"][0].get<double>();
  EXPECT_GT(f4, 0.0);
  EXPECT_NEAR(f1, 0.25 * f4, 1e-9 * f4);
  EXPECT_NEAR(s["increments"][1]["probes"]["tip"][0].get<double>(), 0.2, 1e-12);
}

}  // namespace
// A probe on a body that conducts heat reports its node's temperature, at the end and at every increment.
TEST(Summary, AProbeOnAConductingBodyReportsItsTemperature) {
  const json j = {
      {"dimension", 2},
      {"materials",
       {{{"name", "hot"},
         {"E", 2e5},
         {"nu", 0.3},
         {"conductivity", 30.0},
         {"heat_capacity", 4.5},
         {"temperature", 1000.0}}}},
      {"bodies",
       {{{"name", "b"},
         {"material", "hot"},
         {"mesh", {{"type", "block"}, {"nx", 2}, {"ny", 2}, {"lx", 2.0}, {"ly", 2.0}}}}}},
      {"boundary_conditions",
       {{{"type", "displacement"}, {"body", "b"}, {"set", "xmin"}, {"ux", 0.0}},
        {{"type", "displacement"}, {"body", "b"}, {"set", "ymin"}, {"uy", 0.0}}}},
      {"heat", {{"ambient_temperature", 20.0}, {"air", {{{"body", "b"}, {"surface", "xmax"}, {"convection", 0.5}}}}}},
      {"analysis", {{"increments", 3}, {"duration", 10.0}}},
      {"probes", {{{"name", "corner"}, {"at", {2.0, 2.0}}}}}};
  const Project p = parse_project(j.dump(), "probe.json");
  const Model m = build_model(p);
  const auto s = make_summary(m, run_project(p, m), RunInfo{"probe", "direct"});
  const double end = s["results"]["probes"]["corner"]["temperature"].get<double>();
  EXPECT_LT(end, 1000.0);  // cooled by the air on its face
  EXPECT_GT(end, 20.0);
  ASSERT_EQ(s["increments"].size(), 3u);
  double before = 1000;
  for (const auto& inc : s["increments"]) {
    const double T = inc["probe_temperatures"]["corner"].get<double>();
    EXPECT_LT(T, before);
    before = T;
  }
  EXPECT_DOUBLE_EQ(before, end);
}

}  // namespace rollsim::test_summary
