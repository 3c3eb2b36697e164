#include "mesh/RadiusProfile.h"

#include <algorithm>

namespace rollsim {

double RadiusProfile::at(double y) const {
  if (points.empty()) return 0.0;
  if (y <= points.front().first) return points.front().second;
  if (y >= points.back().first) return points.back().second;
  const auto next = std::upper_bound(points.begin(), points.end(), y,
                                     [](double v, const std::pair<double, double>& p) { return v < p.first; });
  const auto& [y1, r1] = *next;
  const auto& [y0, r0] = *(next - 1);
  return y1 == y0 ? r1 : r0 + (r1 - r0) * (y - y0) / (y1 - y0);
}

double RadiusProfile::lowest() const {
  return points.empty() ? 0.0 : std::min_element(points.begin(), points.end(), [](const auto& a, const auto& b) {
                                  return a.second < b.second;
                                })->second;
}

}  // namespace rollsim
