#pragma once
// What the benchmark cases measure, each with its closed form where one exists: a displacement or nodal stress at
// a point, a support reaction, Hertz's peak pressure, Lamé's thick cylinder.
#include <array>
#include <string>

#include "bench/SuiteCase.h"

namespace rollsim::bench {

/// Component `c` of the displacement of `body`'s node nearest `at` (no closed form).
MeasureFn displacement_at(int body, std::array<double, 3> at, int c);
/// Component `c` (xx, yy, zz, xy, yz, zx) of the averaged nodal stress at `body`'s node nearest `at`.
MeasureFn nodal_stress_at(int body, std::array<double, 3> at, int c);
/// Component `c` of the resultant nodal force (the reaction) on node set `set` of `body`; `exact` its closed form.
MeasureFn reaction_on(int body, const std::string& set, int c, double exact);
/// Peak nodal pressure of contact pair 0 against Hertz's p0 = 2P/(πa), a = √(4PR/(πE*)), P = 2 × the pair's normal
/// force (a half model), 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ (plane strain line contact).
MeasureFn hertz_peak_pressure(double radius, double e1, double nu1, double e2, double nu2);
/// Radial displacement of the inner surface of a thick cylinder (radii a < b, internal pressure p, plane strain)
/// at (a, 0), against Lamé: u(a) = (1 + ν) p a² / (E (b² − a²)) ((1 − 2ν) a + b²/a).
MeasureFn lame_inner_displacement(double a, double b, double p, double e, double nu);

}  // namespace rollsim::bench
