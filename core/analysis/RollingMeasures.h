#pragma once
// The rolling quantities of a pass, measured from the fields of each completed increment: roll force and torque from
// the hub's reactions, contact length from the contact pair, exit thickness and spread from the slab's nodes past
// the exit plane, forward slip from the slab front's advance against the roll's surface travel; then where the roll
// bit and where force and torque settled, and the pressure and shear along the arc at the last increment.
#include "analysis/Results.h"
#include "model/Model.h"

namespace rollsim {

/// Force and torque are settled at an increment when, over the preceding travel of one nominal contact length
/// √(R Δh) (Δh = h0 − h1, the whole draft), neither moved by more than this fraction of its value.
constexpr double kSteadyTolerance = 0.02;

/// The first increment (1-based) whose roll force and torque, and those of every increment over the `window` of
/// travel before it, agree within kSteadyTolerance of its own; 0 when none does (or the travel is shorter).
int steady_state_from(const std::vector<RollingIncrement>& history, double window);

/// The measures of `results` (its increments' fields) for the pass `model.rolling` (which must be set).
RollingResults measure_rolling(const Model& model, const Results& results);

}  // namespace rollsim
