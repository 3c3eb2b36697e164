#include "process/rolling/RollingRun.h"

#include <algorithm>
#include <cstdio>

#include "process/rolling/RollingFacts.h"
#include "process/rolling/RollingMeasures.h"
#include "process/rolling/RollingReport.h"
#include "process/rolling/RollingTheory.h"

namespace rollsim {

RunStatus RollingRun::refusal() const {
  // a pass the roll cannot bite is an answer, not a solver failure: nothing is solved
  if (std::string no_bite = bite_refusal(pass_); !no_bite.empty()) return {Status::no_bite, Reason::none, no_bite};
  return {};
}

std::vector<ProcessFact> RollingRun::facts() const { return rolling_facts(pass_, model_.dim); }

double RollingRun::expected_share() const { return std::min(1.0, travel_through(pass_) / pass_.travel); }

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
  const RollingIncrement r = roll_load(pass_, model_, increment);
  return {r.travel, r.roll_force, r.roll_torque};
}

std::string RollingRun::over(const IncrementResults& increment) const {
  if (increment.bodies.size() != model_.bodies.size()) return {};
  const size_t slab = static_cast<size_t>(pass_.slab);
  const double rear = rear_end(model_.bodies[slab].mesh, increment.bodies[slab].displacement);
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
