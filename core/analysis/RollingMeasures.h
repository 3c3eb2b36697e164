#pragma once
// The rolling quantities of a pass, measured from the fields of each completed increment: roll force and torque from
// the hub's reactions, contact length from the contact pair, exit thickness and spread from the slab's nodes past
// the exit plane, forward slip from the slab front's advance against the roll's surface travel; then where the roll
// bit and where force and torque settled, and the pressure and shear along the arc at the last increment.
#include "analysis/Results.h"
#include "model/Model.h"

namespace rollsim {

/// Force and torque are settled at an increment when their means over the last two windows of travel, each half a
/// nominal contact length √(R Δh) (Δh = h0 − h1, the whole draft), agree within this fraction. Means, not values:
/// on a mesh of finite size the force steps as each slab node enters the arc (±7 % on 36 × 6, ±2.5 % on 72 × 12).
constexpr double kSteadyTolerance = 0.02;
constexpr double kSteadyWindow = 0.5;  // the window, in nominal contact lengths

/// The mean of the increments whose travel lies in (from, to], each weighted by the travel it covered (a cut-back
/// increment counts for its short step).
RollingIncrement window_mean(const std::vector<RollingIncrement>& history, double from, double to);

/// The first increment (1-based) at which the means of roll force and torque over the `window` of travel before it
/// and over the window before that agree within kSteadyTolerance; 0 when none does (or the travel is shorter than
/// two windows).
int steady_state_from(const std::vector<RollingIncrement>& history, double window);

/// One increment's travel, roll force and torque (the rest of the measures need the history: measure_rolling).
RollingIncrement roll_load(const Model& model, const IncrementResults& increment);

/// The measures of `results` (its increments' fields) for the pass `model.rolling` (which must be set).
RollingResults measure_rolling(const Model& model, const Results& results);

}  // namespace rollsim
