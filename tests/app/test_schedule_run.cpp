// `rollsim run` of a rolling schedule (the sample rolling-2d-schedule, short passes): each pass's results in
// pass-<n>/, the schedule's table, chart and summary beside them, exit 0; a pass thicker than what it receives is
// refused with its path, exit 2; a shorter schedule run into the same folder leaves no pass folder of the longer one.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_schedule_run {

using json = nlohmann::json;

namespace {
const std::string sample = ROLLSIM_SOURCE_DIR "/samples/rolling-2d-schedule.json";

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}
}  // namespace

TEST(ScheduleRun, EachPassWritesItsFolderAndTheScheduleItsTable) {
  const std::string out = make_temp_dir("schedule");
  const RunResult r = run_rollsim(
      {"run", sample, "--out", out, "--set", "process.travel=8", "--set", "process.travel_increment=2"}, 240);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto names = list_dir(out);
  for (const char* name : {"pass-1", "pass-2", "pass-3", "schedule.csv", "schedule.png", "summary.json"})
    EXPECT_TRUE(has(names, name)) << name;
  EXPECT_TRUE(has(list_dir(out + "/pass-2"), "rolling.csv"));
  const json summary = json::parse(read_text(out + "/summary.json"));
  EXPECT_EQ(summary.at("status"), "converged");
  const json& passes = summary.at("schedule").at("passes");
  ASSERT_EQ(passes.size(), 3u);
  EXPECT_EQ(passes[1].at("interpass_time"), 8.0);
  EXPECT_EQ(passes[2].at("roll_speed"), 50.0);
  // each pass receives what the pass before left, its mean temperature after the air
  EXPECT_NEAR(passes[1].at("entry_thickness").get<double>(), passes[0].at("exit_thickness").get<double>(), 1e-9);
  EXPECT_LT(passes[1].at("entry_temperature").get<double>(), passes[0].at("entry_temperature").get<double>());
  const std::string csv = read_text(out + "/schedule.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4) << csv;
  // the same folder again with one pass: the longer schedule's pass folders go with its other results
  json one = json::parse(read_text(sample));
  one["process"]["passes"] = json::array({one["process"]["passes"][0]});
  write_text(out + "/one-pass.json", one.dump());
  const RunResult again = run_rollsim(
      {"run", out + "/one-pass.json", "--out", out, "--set", "process.travel=4", "--set", "process.travel_increment=2"},
      240);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(has(list_dir(out), "pass-1"));
  EXPECT_FALSE(has(list_dir(out), "pass-2"));
  EXPECT_FALSE(has(list_dir(out), "pass-3"));
  EXPECT_TRUE(has(list_dir(out), "one-pass.json")) << "the user's own file stays";
}

TEST(ScheduleRun, APassThickerThanWhatItReceivesIsRefusedWithItsPath) {
  const std::string out = make_temp_dir("schedule-bad");
  json bad = json::parse(read_text(sample));
  bad["process"]["passes"][1] = {{"exit_thickness", 90.0}};  // pass 1 leaves 80 mm
  write_text(out + "/bad.json", bad.dump());
  const RunResult r = run_rollsim({"run", out + "/bad.json", "--out", out + "/results"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("process.passes[1].exit_thickness: 90 mm is not below the 80 mm the pass receives"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(has(list_dir(out), "results")) << "refused before anything is written";
}

}  // namespace test_schedule_run
