#pragma once
// How close an element of a deformed mesh is to folding: at each corner the Jacobian of the corner's edges (2D: the
// cross product of its two edges, 3D: the triple product of its three), deformed over undeformed; the element's
// quality is the smallest — 1 for a rigid motion, small before the element folds, ≤ 0 once it has. Written as the
// `jacobian_ratio` cell field, so the element a failed run names can be found in ParaView.
#include "mesh/Mesh.h"

namespace rollsim {

/// Smallest corner Jacobian ratio of element `e` of `mesh` displaced by `u` (dim values per node).
double corner_jacobian_ratio(const Mesh& mesh, const double* u, int e);

}  // namespace rollsim
