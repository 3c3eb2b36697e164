#pragma once
// Randomly distorted meshes for the stability suite: interior nodes moved, the boundary kept, so that the problem
// (and its closed form) stays the same while the elements lose their shape.
#include "mesh/Mesh.h"

namespace rollsim::bench {

/// Moves every node that belongs to no named node set (other than "all") by a uniform random offset of up to
/// `fraction` × its shortest incident edge in each component, seeded by `seed`. Nodes of sets (the boundary and
/// the sets a project names) stay where they are.
void distort_interior_nodes(Mesh& mesh, double fraction, unsigned seed);

}  // namespace rollsim::bench
