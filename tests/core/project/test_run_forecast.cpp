// The run forecast: the model's dofs and elements, the process's facts and refusal, the increments a pass is
// expected to take (its slab through the gap), Newton iterations against solves, and a time that grows with the
// mesh and with the factor a solver computes at every iteration.
#include "project/RunForecast.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "process/Process.h"
#include "project/ModelBuilder.h"
#include "project/Overrides.h"
#include "project/Project.h"

namespace test_run_forecast {

using namespace rollsim;

namespace {
/// `sets`: {path, value} as --set takes them.
RunForecast forecast_of(const std::string& sample, const std::vector<std::pair<std::string, std::string>>& sets = {}) {
  Overrides overrides;
  for (const auto& [path, value] : sets) overrides.sets.push_back({path, value, "--set"});
  Project p = load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / (sample + ".json"), overrides);
  return forecast_run(p.config(), build_model(p));
}
}  // namespace

TEST(RunForecast, ARollingPassCountsItsModelItsFactsAndItsIncrements) {
  const RunForecast f = forecast_of("rolling-2d-36x6");
  const Project p = load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples/rolling-2d-36x6.json");
  const Model m = build_model(p);
  EXPECT_EQ(f.elements, m.total_elements());
  EXPECT_GT(f.dofs, 0);
  EXPECT_LT(f.dofs, 2 * m.total_nodes());  // the hub's nodes and the mid-plane's y are prescribed
  EXPECT_TRUE(f.refusal.ok());
  EXPECT_FALSE(f.facts.empty());
  EXPECT_EQ(f.increments, p.config().steps.increments);  // 120 mm of travel on a 300 mm slab: all of it
  EXPECT_FALSE(f.linear);
  EXPECT_GT(f.iterations, f.increments);
  EXPECT_GT(f.factor_flops, 0);
  EXPECT_GT(f.seconds, f.iterations * f.seconds_per_iteration);  // and what each increment writes
  EXPECT_NE(forecast_line(f).find("Newton iterations"), std::string::npos) << forecast_line(f);
}

TEST(RunForecast, APassLongerThanItsSlabIsForecastToEndWhenTheSlabIsThrough) {
  const RunForecast whole = forecast_of("rolling-2d-36x6", {{"process.travel", "500"}});
  // the rear end enters the gap near 267 mm of travel: 267 / 500 of the increments
  const int asked = static_cast<int>(std::ceil(500 / 1.0));
  EXPECT_LT(whole.increments, asked * 0.6);
  EXPECT_GT(whole.increments, asked * 0.5);
}

// A 3D ALE window steady at the earliest once its first material has left it (its length, not two windows of half a
// contact length: 282 of its 400 mm); its steps start near their answers (the flow repeats: 3 Newton iterations an
// increment, 2.1 measured on the sample); its fixed roll is factored once, where a turning one is refactored.
TEST(RunForecast, AnAleWindowIsForecastToItsLengthInFewIterationsAndAFixedRollFactoredOnce) {
  const RunForecast fixed = forecast_of("rolling-3d-ale");
  EXPECT_EQ(fixed.increments, 282);
  EXPECT_DOUBLE_EQ(fixed.iterations, 3.0 * fixed.increments);
  bool said = false;
  for (const ProcessFact& f : fixed.facts)
    said = said || (f.name == "end of the pass" && f.value == "travel ≈ 282 mm" &&
                    f.note.find("the window's first material has left it") != std::string::npos);
  EXPECT_TRUE(said);
  const RunForecast turning = forecast_of("rolling-3d-ale", {{"process.roll_mesh", "turning"}});
  EXPECT_GT(turning.seconds_per_iteration, 1.5 * fixed.seconds_per_iteration);
  const RunForecast plane = forecast_of("rolling-2d-ale");  // two windows of half a contact length: 63 mm
  EXPECT_EQ(plane.increments, static_cast<int>(std::ceil(2 * 0.5 * std::sqrt(300 * 13.2) / 2.5 - 1e-9)));
}

TEST(RunForecast, APassThatCannotBiteForecastsNothingSolved) {
  const RunForecast f =
      forecast_of("rolling-2d-36x6", {{"process.friction", "coulomb"}, {"process.friction_coefficient", "0.1"}});
  EXPECT_FALSE(f.refusal.ok());
  EXPECT_EQ(f.seconds, 0);
  EXPECT_EQ(forecast_line(f).rfind("nothing will be solved: the roll cannot draw the slab in", 0), 0u)
      << forecast_line(f);
}

TEST(RunForecast, ALinearRunCountsSolvesAndAFinerMeshCostsMore) {
  const RunForecast coarse = forecast_of("cantilever-2d-240x60"), fine = forecast_of("cantilever-2d-120x120");
  EXPECT_TRUE(coarse.linear);
  EXPECT_EQ(coarse.iterations, 1);
  EXPECT_NE(forecast_line(coarse).find("1 solve"), std::string::npos) << forecast_line(coarse);
  EXPECT_TRUE(coarse.facts.empty());
  // 14 400 elements either way, but the square's factor is denser than the strip's
  EXPECT_GT(fine.factor_flops, coarse.factor_flops);
  EXPECT_GT(fine.seconds, coarse.seconds);
}

}  // namespace test_run_forecast
