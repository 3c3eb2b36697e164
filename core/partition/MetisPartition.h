#pragma once
// METIS k-way partition of the element dual graph (elements joined by a shared edge in 2D, face in 3D).
#include "mesh/Mesh.h"
#include "partition/Partition.h"

namespace rollsim {

/// `parts` subdomains of about equal element counts with a small cut, by METIS_PartGraphKway with a fixed seed
/// (deterministic) and contiguous parts requested when the body itself is connected. Throws PartitionError
/// for parts < 1 or more parts than elements, or when METIS fails.
Partition metis_partition(const Mesh& mesh, int parts);

}  // namespace rollsim
