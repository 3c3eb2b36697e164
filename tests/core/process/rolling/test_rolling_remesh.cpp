// A Lagrangian rolling pass that remeshes (analysis.remesh_quality): its segments are one pass — the live measures
// count travel on from each remesh as the final table does, the forward slip does not jump where a remesh spreads the
// slab's front face again, and the force stays the unremeshed pass's within what the transfer smears; an ALE window and
// a schedule, which cannot take a remesh, are refused at the user's path.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "../../../common/PassRun.h"
#include "../../../common/RollingPass.h"
#include "../../../common/RunJson.h"
#include "base/Observer.h"

namespace test_rolling_remesh {

using namespace rollsim;

namespace {
/// The travel of every row the run tells its observer while it runs.
class LiveTravel final : public AnalysisObserver {
 public:
  void on_measured(int /*increment*/, const MeasureRow& row) override { travel.push_back(row.at(0)); }
  std::vector<double> travel;
};
}  // namespace

TEST(RollingRemesh, APassThatRemeshesIsOnePassWithTheUnremeshedForce) {
  const nlohmann::json plain = testing_support::paper_pass_2d(30, 1.0);
  nlohmann::json remeshed = plain;
  remeshed["analysis"] = {{"remesh_quality", 0.95}};  // the coarse slab's worst corner falls to 0.95 every ~8 mm
  const testing_support::PassRun a = testing_support::run_pass(plain);
  const Project p = parse_project(remeshed.dump(), "remeshed");
  const Model m = build_model(p);
  LiveTravel live;
  const Results r = run_project(p, m, &live);
  ASSERT_EQ(a.status.status, Status::converged) << a.status.message;
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  ASSERT_GE(r.remeshes.size(), 2u);
  EXPECT_EQ(r.remeshes[0].body, "slab");
  const RollingResults b = measure_rolling(rolling_pass(p.data.at("process"), m), m, r);
  ASSERT_EQ(live.travel.size() + 1, b.increments.size());  // the last increment is measured once the run has ended
  for (size_t i = 0; i < live.travel.size(); ++i)          // each segment's travel counted on from the remesh, live too
    EXPECT_NEAR(live.travel[i], b.increments[i].travel, 1e-9) << i;
  EXPECT_NEAR(b.increments.back().travel, 30, 1e-9);
  // no jump in the forward slip where a remesh spreads the front face's nodes again: across each remesh it moves
  // as little as over the step before it
  for (const RemeshRecord& rec : r.remeshes) {
    const size_t k = static_cast<size_t>(rec.increment);  // the first increment after the remesh (0-based)
    ASSERT_GE(k, 2u);
    ASSERT_LT(k, b.increments.size());
    const double across = std::abs(b.increments[k].forward_slip - b.increments[k - 1].forward_slip);
    const double before = std::abs(b.increments[k - 1].forward_slip - b.increments[k - 2].forward_slip);
    EXPECT_LT(across, 2 * before + 1e-3) << "remesh after increment " << k;
  }
  const RollingIncrement& x = a.rolling->increments.back();
  const RollingIncrement& y = b.increments.back();
  EXPECT_NEAR(y.roll_force / x.roll_force, 1, 0.02);
  EXPECT_NEAR(y.forward_slip, x.forward_slip, 0.005);
  EXPECT_NEAR(y.volume_change, 0, 1e-3);  // the transfer keeps the slab's volume (its shape is not changed)
}

// The hot pass with heat on 54 x 9 remeshes once near 26 mm. The slab's temperature is carried with its integral
// (interpolated alone, the 36 x 6 slab's mean fell 1.3 K in its remesh), and every conducting body's points start from
// their nodes' temperatures (the roll's started from none, and its hottest node fell 10 K in the first step after the
// remesh).
TEST(RollingRemesh, AHotPassKeepsItsHeatAcrossARemesh) {
  std::ifstream file(std::string(ROLLSIM_SOURCE_DIR) + "/samples/rolling-2d-heat.json");
  nlohmann::json hot = nlohmann::json::parse(file);
  hot["process"].update({{"slab_nx", 54}, {"slab_nt", 9}, {"travel", 30.0}});
  hot["analysis"] = {{"remesh_quality", 0.5}};
  hot.erase("solver");
  hot["solver"] = {{"mode", "direct"}};
  const testing_support::PassRun r = testing_support::run_pass(hot);
  ASSERT_EQ(r.status.status, Status::converged) << r.status.message;
  ASSERT_GE(r.remeshes.size(), 1u);
  const RemeshRecord& m = r.remeshes[0];
  ASSERT_TRUE(std::isfinite(m.mean_temperature_before));
  EXPECT_LT(m.mean_temperature_before, 1100.0);
  EXPECT_NEAR(m.mean_temperature_after, m.mean_temperature_before, 0.02);
  const auto& h = r.rolling->increments;
  const size_t k = static_cast<size_t>(m.increment);  // the first increment after the remesh
  ASSERT_LT(k, h.size());
  EXPECT_NEAR(h[k].slab_temperature, h[k - 1].slab_temperature, 0.05);
  EXPECT_NEAR(h[k].roll_temperature, h[k - 1].roll_temperature, 1.0);
}

TEST(RollingRemesh, AnAleWindowAndAScheduleRefuseARemesh) {
  nlohmann::json ale = testing_support::paper_pass_2d(10, 1.0);
  ale["process"]["formulation"] = "ale";
  ale["analysis"] = {{"remesh_quality", 0.5}};
  EXPECT_NE(
      testing_support::refusal_of(ale).find("analysis.remesh_quality: has no effect with process.formulation: ale"),
      std::string::npos)
      << testing_support::refusal_of(ale);
  nlohmann::json schedule = testing_support::paper_pass_2d(10, 1.0);
  schedule["process"].erase("travel");
  schedule["process"]["passes"] = {{{"reduction", 0.1}}, {{"reduction", 0.1}}};
  schedule["analysis"] = {{"remesh_quality", 0.5}};
  EXPECT_NE(testing_support::refusal_of(schedule).find("analysis.remesh_quality: a schedule (process.passes)"),
            std::string::npos)
      << testing_support::refusal_of(schedule);
  nlohmann::json lagrangian = testing_support::paper_pass_2d(10, 1.0);
  lagrangian["analysis"] = {{"remesh_quality", 0.5}};
  EXPECT_EQ(testing_support::refusal_of(lagrangian), "accepted");
}

}  // namespace test_rolling_remesh
