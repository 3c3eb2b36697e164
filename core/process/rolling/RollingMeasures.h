#pragma once
// The rolling quantities of a pass, measured from the fields of each completed increment: roll force and torque from
// the hub's reactions, contact length from the contact pair, exit thickness and spread from the slab's nodes past
// the exit plane, forward slip from the slab front's advance against the roll's surface travel; then where the roll
// bit and where force and torque settled, and the pressure and shear along the arc at the last increment.
#include <vector>

#include "analysis/Results.h"
#include "base/Measures.h"
#include "model/Model.h"
#include "process/rolling/RollingPass.h"
#include "process/rolling/RollingResults.h"

namespace rollsim {

/// One measure of a pass: its name, label and unit (plane strain: per unit width; 3D: its unit there), and the
/// member of RollingIncrement that holds it. The table is the pass's columns in rolling.csv, the keys and units of
/// summary.json's results.rolling and what window means average: a new measure is its member, its line here and
/// its computation in measure_rolling.
struct RollingMeasure {
  Measure plane;           // name, label, unit in plane strain
  std::string solid_unit;  // the unit in 3D
  double RollingIncrement::*field;
  bool thermal = false;       // reported only when the slab has a temperature (RollingResults::thermal)
  Measure in(int dim) const;  // the measure as a model of dimension `dim` reports it
};
const std::vector<RollingMeasure>& rolling_measures();

/// Force and torque are settled at an increment when their means over the last two windows of travel, each half a
/// nominal contact length √(R Δh) (Δh = h0 − h1, the whole draft), agree within this fraction. Means, not values:
/// on a mesh of finite size the force steps as each slab node enters the arc (±7 % on 36 × 6, ±2.5 % on 72 × 12).
constexpr double kSteadyTolerance = 0.02;
constexpr double kSteadyWindow = 0.5;  // the window, in nominal contact lengths

/// The mean of the increments whose travel lies in (from, to], each weighted by the travel it covered (a cut-back
/// increment counts for its short step).
RollingIncrement window_mean(const std::vector<RollingIncrement>& history, double from, double to);

/// The spread a mean-width window may still change by and count as steady, besides kSteadyTolerance of it [length].
constexpr double kSteadySpread = 0.01;

/// The first increment (1-based) at which the means of roll force and torque over the `window` of travel before it
/// and over the window before that agree within kSteadyTolerance — with `shape`, the mean spread's too (within
/// kSteadyTolerance of it plus kSteadySpread: an ALE pass in 3D, whose force settles long before its free side does),
/// and every spread of the last window within that band about its mean (no overshoot on its way down), and not
/// before `flushed` mm of travel (an ALE window's length: the side's shape is carried out of the window by its
/// material, and until the material it started with has left, what leaves was not rolled from the entry); 0 when
/// none does (or the travel is shorter than two windows).
int steady_state_from(const std::vector<RollingIncrement>& history, double window, bool shape = false,
                      double flushed = 0);

/// Whether a pass's steady state asks for its free side's shape too (steady_state_from's `shape`): an ALE window in 3D.
inline bool shape_steady(const RollingPass& pass) { return pass.ale && pass.width_axis >= 0; }

/// The travel at which a pass can be steady at the earliest under steady_state_from: two windows of half a nominal
/// contact length, and with the shape the ALE window's length (the material it started with gone) [length].
double earliest_steady_travel(const RollingPass& pass);

/// An increment's exit thickness, spread and mean spread (RollingIncrement's; the rest zero), from the slab's nodes
/// past the exit plane on the increment's model.
RollingIncrement exit_shape(const RollingPass& pass, const Model& model, const IncrementResults& increment);

/// ∫ N_a dV of every node of the mesh as meshed: its share of the body's volume (the weights of a volume mean).
Eigen::VectorXd node_volumes(const Mesh& mesh);

/// A body's temperature at its nodes: conducted, or its elements' (their points' adiabatic rises) averaged onto
/// them; empty when it has none.
Eigen::VectorXd node_temperatures(const Mesh& mesh, const BodyResults& r);

/// Where the slab's rear end is along x (the mean of its node set xmin, deformed): the pass is over once it reaches
/// the entry of the arc of contact.
double rear_end(const Mesh& slab, const Eigen::VectorXd& u);

/// One increment's travel, roll force and torque (the rest of the measures need the history: measure_rolling).
RollingIncrement roll_load(const RollingPass& pass, const Model& model, const IncrementResults& increment);

/// The measures of `results` (its increments' fields) for `pass` on `model` (built from its process).
RollingResults measure_rolling(const RollingPass& pass, const Model& model, const Results& results);

}  // namespace rollsim
