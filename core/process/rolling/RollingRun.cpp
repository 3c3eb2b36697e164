#include "process/rolling/RollingRun.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "process/rolling/RollingAle3d.h"
#include "process/rolling/RollingFacts.h"
#include "process/rolling/RollingMeasures.h"
#include "process/rolling/RollingReport.h"
#include "process/rolling/RollingTheory.h"

namespace rollsim {

RollingRun::RollingRun(RollingPass pass, const Model& model) : pass_(std::move(pass)), model_(model) {
  if (pass_.ale && model_.dim == 2) ale_ = std::make_unique<RollingAle>(pass_, model_);
  if (pass_.ale && model_.dim == 3) ale_ = std::make_unique<RollingAle3d>(pass_, model_);
}

RunStatus RollingRun::refusal() const {
  // a pass the roll cannot bite is an answer, not a solver failure: nothing is solved
  if (std::string no_bite = bite_refusal(pass_); !no_bite.empty()) return {Status::no_bite, Reason::none, no_bite};
  return {};
}

std::vector<ProcessFact> RollingRun::facts() const { return rolling_facts(pass_, model_.dim); }

double RollingRun::expected_share() const {
  if (!pass_.ale) return std::min(1.0, travel_through(pass_) / pass_.travel);
  // an ALE slab never runs out; steady, its force is flat, so the 2 % rule holds as soon as it can
  return pass_.stop_at_steady ? std::min(1.0, earliest_steady_travel(pass_) / pass_.travel) : 1.0;
}

MeasureTable RollingRun::live_table() const {
  MeasureTable t = history_table({}, model_.dim);
  const auto keep = [&](const Measure& m) {
    return m.name == "travel" || m.name == "roll_force" || m.name == "roll_torque";
  };
  std::vector<Measure> live;
  for (const Measure& m : t.columns)
    if (keep(m)) live.push_back(m);
  t.columns = live;
  return t;
}

ChartRequest RollingRun::live_chart() const { return history_chart(pass_, model_.dim, {}, false); }

MeasureRow RollingRun::measure(const IncrementResults& increment) const {
  RollingIncrement r = roll_load(pass_, model_, increment);
  if (shape_steady(pass_)) r.mean_spread = exit_shape(pass_, model_, increment).mean_spread;
  while (!live_.empty() && live_.back().travel >= r.travel) live_.pop_back();  // measured again: a repeated step
  live_.push_back(r);
  return {r.travel, r.roll_force, r.roll_torque};
}

std::string RollingRun::steady() const {
  const double window = kSteadyWindow * rolling_theory(pass_).contact_length;
  const int from = steady_state_from(live_, window, shape_steady(pass_), pass_.ale_entry + pass_.ale_exit);
  if (from == 0) return {};
  char text[400];
  std::snprintf(text, sizeof text,
                "the pass is steady at travel %.4g mm (process.stop_at_steady_state): the means of roll force and "
                "torque%s over the last two windows of %.3g mm of travel agree within %g %%",
                live_[static_cast<size_t>(from - 1)].travel, shape_steady(pass_) ? " and the mean spread" : "", window,
                100 * kSteadyTolerance);
  std::string said = text;
  if (shape_steady(pass_)) {
    std::snprintf(text, sizeof text,
                  ", the spread within %g %% + %g mm at every increment of the last window, and the window's first "
                  "material has left it (%.4g mm of travel)",
                  100 * kSteadyTolerance, kSteadySpread, pass_.ale_entry + pass_.ale_exit);
    said += text;
  }
  return said;
}

std::string RollingRun::over(const IncrementResults& increment) const {
  if (increment.bodies.size() != model_.bodies.size()) return {};
  if (pass_.stop_at_steady)
    if (std::string s = steady(); !s.empty()) return s;
  if (pass_.ale) return {};  // the window's material never runs out
  const size_t slab = static_cast<size_t>(pass_.slab);
  const double rear = rear_end(model_of(increment, model_).bodies[slab].mesh, increment.bodies[slab].displacement);
  const double entry = -rolling_theory(pass_).contact_length;  // the roll axis is at x = 0, the slab moves along +x
  if (rear < entry) return {};
  char text[400];
  std::snprintf(text, sizeof text,
                "the pass is complete at travel %.4g mm: the slab's rear end has entered the roll gap (x = %.1f mm, "
                "the arc of contact starts at x = %.1f mm); process.travel asked for %.4g mm, but the slab, drawn in "
                "by friction alone, is not followed out of the roll",
                increment.load_factor * pass_.travel, rear, entry, pass_.travel);
  return text;
}

ProcessResults RollingRun::finish(const Results& results) const {
  return rolling_results(pass_, model_.dim, measure_rolling(pass_, model_, results));
}

}  // namespace rollsim
