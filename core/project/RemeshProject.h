#pragma once
// What a run that remeshes (analysis.remesh_quality > 0: analysis/Remeshing) may hold, checked at the user's paths: 2D
// quad bodies, every one finite-strain (each segment restarts every body from its current shape, and only a
// finite-strain state, b_e, carries a body's stress there), motion prescribed and no loads (a load would have to be
// held at its level across the segments). A process says for itself where it cannot take a remesh (a rolling pass:
// an ALE window, a schedule).
#include <vector>

#include "base/Schema.h"

namespace rollsim {

/// The remeshing run's requirements on a project (`expanded`: its process expanded).
void check_remesh(const json& expanded, int dim, std::vector<Issue>& issues);

}  // namespace rollsim
