#pragma once
// Bounds on a model's size derived from index width and memory, checked on the project before any mesh is made:
// the assembled stiffness uses 32-bit sparse indices (at most 2^31 − 1 nonzeros), and assembling it needs memory
// in proportion to the elements. A request beyond either is refused with the estimate in the message.
#include <vector>

#include "base/Schema.h"

namespace rollsim {

/// What the stiffness of a mesh of `elements` linear elements (Q4 in 2D, H8 in 3D) needs, estimated for a
/// structured mesh (about one node per element, each coupled to 3^dim nodes).
struct StiffnessEstimate {
  double nonzeros = 0;  // stored entries of the assembled K (both triangles)
  double bytes = 0;     // memory of its assembly: scatter map, node graph, pattern and two value arrays
};
StiffnessEstimate estimate_stiffness(double elements, int dim);

/// Physical memory of this machine [bytes] (sysconf); 0 when unknown.
double physical_memory_bytes();

/// Issues (at `path`) for a model of `elements` elements beyond the 32-bit index limit or this machine's memory.
void check_model_limits(double elements, int dim, const std::string& path, std::vector<Issue>& issues);

}  // namespace rollsim
