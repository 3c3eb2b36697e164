#pragma once
// A material's thermal properties against temperature, as the project's materials[].thermal_table gives them:
// conductivity k(T) and volumetric heat capacity ρc(T), piecewise linear between the table's temperatures and
// constant beyond its first and last (analysis/HeatConduction reads them at the step's start temperatures).
#include <algorithm>
#include <vector>

namespace rollsim {

struct ThermalTable {
  std::vector<double> temperature;    // [°C], strictly increasing; empty: no table
  std::vector<double> conductivity;   // k at each temperature [W/(m K) = N/(s K)]; empty: the material's constant
  std::vector<double> heat_capacity;  // ρc at each temperature [stress / K]; empty: the material's constant

  bool empty() const { return temperature.empty(); }
  bool gives_conductivity() const { return !conductivity.empty(); }
  bool gives_heat_capacity() const { return !heat_capacity.empty(); }
  /// Whether T lies within the table's temperatures (outside it the properties are held at the end values).
  bool covers(double T) const { return !empty() && T >= temperature.front() && T <= temperature.back(); }
  double conductivity_at(double T) const { return at(conductivity, T); }
  double heat_capacity_at(double T) const { return at(heat_capacity, T); }

 private:
  /// values(T): linear between the two temperatures around T, the end value beyond either end.
  double at(const std::vector<double>& values, double T) const {
    if (T <= temperature.front()) return values.front();
    if (T >= temperature.back()) return values.back();
    const size_t i = static_cast<size_t>(std::upper_bound(temperature.begin(), temperature.end(), T) -
                                         temperature.begin());  // temperature[i - 1] ≤ T < temperature[i]
    const double s = (T - temperature[i - 1]) / (temperature[i] - temperature[i - 1]);
    return values[i - 1] + s * (values[i] - values[i - 1]);
  }
};

}  // namespace rollsim
