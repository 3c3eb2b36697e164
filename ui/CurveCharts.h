#pragma once
// Plain x–y curves on linear axes, rendered offscreen to a PNG: one colour per computed curve (a line through its
// points), and reference points (e.g. read off a published figure) as black rings. For the validation scripts'
// plots (tests/bench/necking_curve.cpp), which need no display.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rollsim::ui {

struct Curve {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y)
  bool reference = false;                         // drawn as rings, not joined
};

/// Writes the chart as a PNG of 1000 × 600 pixels (atomically); the y axis spans [y_min, the data's max] when y_min
/// is below every point, else the data's range. Runs its own offscreen QApplication when none exists. Throws
/// std::runtime_error when the file cannot be written.
void write_curves_png(const std::filesystem::path& file, const std::string& title, const std::string& x_title,
                      const std::string& y_title, const std::vector<Curve>& curves, double y_min);

}  // namespace rollsim::ui
