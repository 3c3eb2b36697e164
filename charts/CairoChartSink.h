#pragma once
// The chart sink of `rollsim run`, with or without the window: a process's charts (core's ChartRequest over a
// MeasureTable) drawn as PNG by cairo — lines with their points marked, dashed references, a left and a right axis
// with nice ticks, a legend — with no display, no Qt and no VTK. Cairo is linked PRIVATE: no cairo header leaks.
#include "io/ChartSink.h"

namespace rollsim::charts {

class CairoChartSink final : public ChartSink {
 public:
  CairoChartSink(int width = 1000, int height = 600) : width_(width), height_(height) {}
  std::string png(const ChartRequest& chart, const MeasureTable& table) const override;

 private:
  int width_, height_;
};

}  // namespace rollsim::charts
