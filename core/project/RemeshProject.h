#pragma once
// What a run that remeshes (analysis.remesh_quality > 0: analysis/Remeshing) may hold, checked at the user's paths: 2D
// quad bodies, every one finite-strain (each segment restarts every body from its current shape, and only a
// finite-strain state, b_e, carries a body's stress there), motion prescribed and no loads (a load would have to be
// held at its level across the segments), no process (a rolling pass has its own meshes: its ALE steady state is not
// built).
#include <vector>

#include "base/Schema.h"

namespace rollsim {

/// The remeshing run's requirements on a project (`given`: as the user wrote it; `expanded`: its process expanded).
void check_remesh(const json& given, const json& expanded, int dim, std::vector<Issue>& issues);

}  // namespace rollsim
