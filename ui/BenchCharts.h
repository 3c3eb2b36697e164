#pragma once
// The accuracy suite drawn: run time against error on log–log axes, one colour per solver mode (every run marked,
// the mode's own best runs joined), the family's Pareto front dashed and ringed. `rollsim bench accuracy` writes
// one PNG per family, rendered offscreen (no display needed).
#include <filesystem>
#include <string>
#include <vector>

namespace rollsim::ui {

struct TimeErrorPoint {
  double time = 0;   // wall seconds
  double error = 0;  // relative
};

struct TimeErrorSeries {
  std::string name;  // the mode
  std::vector<TimeErrorPoint> points;
};

/// Writes the chart as a PNG of 1000 × 650 pixels (atomically); `front` is the Pareto front over all series. Runs
/// its own offscreen QApplication when none exists. Throws std::runtime_error when the file cannot be written.
void write_time_error_png(const std::filesystem::path& file, const std::string& title,
                          const std::vector<TimeErrorSeries>& series, std::vector<TimeErrorPoint> front);

}  // namespace rollsim::ui
