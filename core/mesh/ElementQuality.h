#pragma once
// How close an element of a deformed mesh is to folding: at each corner the Jacobian of the corner's edges (2D: the
// cross product of its two edges, 3D: the triple product of its three), deformed over undeformed; the element's
// quality is the smallest — 1 for a rigid motion, small before the element folds, ≤ 0 once it has. Written as the
// `jacobian_ratio` cell field, so the element a failed run names can be found in ParaView.
#include <array>
#include <vector>

#include "mesh/Mesh.h"

namespace rollsim {

/// Smallest corner Jacobian ratio of element `e` of `mesh` displaced by `u` (dim values per node).
double corner_jacobian_ratio(const Mesh& mesh, const double* u, int e);

/// The shape of element `e` of `mesh` with its nodes at `x`: its smallest corner Jacobian over the product of the
/// corner's edge lengths — the sine of its sharpest corner (2D), 1 for right angles, ≤ 0 once a corner has folded.
double corner_sine(const Mesh& mesh, const std::vector<std::array<double, 3>>& x, int e);

}  // namespace rollsim
