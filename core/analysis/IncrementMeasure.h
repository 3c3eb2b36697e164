#pragma once
// The measures of each completed increment that an analysis tells its observer while it runs (a rolling pass: roll
// travel, force and torque), from a process (core/process/) the analysis knows only through this interface.
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
};

}  // namespace rollsim
