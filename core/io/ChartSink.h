#pragma once
// Where a run's charts are drawn: the writer (io/RunWriter) hands each ChartRequest of a process, with its table, to
// the sink the front end injects (charts/CairoChartSink in `rollsim run`, with or without the window), and writes
// the PNG bytes it returns.
#include <string>

#include "base/Measures.h"

namespace rollsim {

class ChartSink {
 public:
  virtual ~ChartSink() = default;
  /// The chart as PNG bytes; throws std::runtime_error when it cannot be drawn.
  virtual std::string png(const ChartRequest& chart, const MeasureTable& table) const = 0;
};

}  // namespace rollsim
