#pragma once
// Two displacement (or symmetry) conditions that prescribe the same component of the same node differently are
// refused with both JSON paths — before, the last one silently won.
#include <vector>

#include "base/Schema.h"
#include "model/Model.h"

namespace rollsim {

/// One issue per pair of conditions in conflict (at the first node where they disagree), at the later one's path.
/// DisplacementBC::source names each condition's index in the project's boundary_conditions.
std::vector<Issue> prescribed_conflicts(const Model& model);

}  // namespace rollsim
