#pragma once
// A radius that changes along an axis — a crowned, tapered or grooved roll: the change Δr from a nominal radius at
// points along the axis, linear between them and constant beyond the first and the last.
#include <utility>
#include <vector>

namespace rollsim {

struct RadiusProfile {
  std::vector<std::pair<double, double>> points;  // (axial position, Δr) by ascending position (length)

  /// Δr at axial position y (0 without points).
  double at(double y) const;
  /// The smallest Δr of the points (0 without points): the radius is smallest there.
  double lowest() const;
};

}  // namespace rollsim
