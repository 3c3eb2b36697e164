#pragma once
// The paper's partitions (Tables VIII–XI, XV–XVII): X×Y(×Z) slicing of a body.
#include <array>

#include "mesh/Mesh.h"
#include "partition/Partition.h"

namespace rollsim {

/// Slices the body's bounding box into slices[0] × slices[1] (× slices[2]) equal boxes and puts each element
/// into the box of its centroid; subdomain id = ix + sx (iy + sy iz). On a structured block whose element
/// counts are multiples of the slice counts this is exactly index slicing (centroids sit half an element away
/// from every cut). Throws PartitionError for counts below 1 or a z slicing of a 2D body.
Partition structured_partition(const Mesh& mesh, const std::array<int, 3>& slices);

}  // namespace rollsim
