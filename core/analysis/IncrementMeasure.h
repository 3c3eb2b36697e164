#pragma once
// The measures of each completed increment that an analysis tells its observer while it runs (a rolling pass: roll
// travel, force and torque), and whether the process is over there, from a process (core/process/) the analysis knows
// only through this interface.
#include <string>

#include "analysis/Results.h"
#include "base/Measures.h"
#include "model/Model.h"

namespace rollsim {

class IncrementMeasure {
 public:
  virtual ~IncrementMeasure() = default;
  /// The columns measured per increment, with no rows, and the chart that plots them as they come.
  virtual MeasureTable live_table() const = 0;
  virtual ChartRequest live_chart() const = 0;
  /// The row of live_table()'s columns for a completed increment.
  virtual MeasureRow measure(const IncrementResults& increment) const = 0;
  /// Why the process is over after this completed increment (a rolling pass: the slab's rear end has entered the
  /// roll gap), or empty. The analysis ends there, converged, with this as its message and the increments done as its
  /// result.
  virtual std::string over(const IncrementResults& /*increment*/) const { return {}; }
};

}  // namespace rollsim
