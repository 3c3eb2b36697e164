#pragma once
// A rolling pass in a mill engineer's terms, before it is solved: reduction, roll size, bite angle, contact length,
// whether the roll bites with the chosen friction, the closed forms' roll force and torque, where the pass will end,
// and, with a roll speed, the surface speed, the time in the gap, the mean strain rate and the roll power.
#include <vector>

#include "process/Process.h"
#include "process/rolling/RollingPass.h"

namespace rollsim {

/// The facts of `pass` in a model of dimension `dim` (2: per unit width, and for the slab's width in plane strain).
std::vector<ProcessFact> rolling_facts(const RollingPass& pass, int dim);

}  // namespace rollsim
