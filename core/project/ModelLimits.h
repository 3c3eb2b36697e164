#pragma once
// Bounds on a model's size derived from index width and memory, checked on the project before any mesh is made:
// the assembled stiffness uses 32-bit sparse indices (at most 2^31 − 1 nonzeros), and assembling it needs memory
// in proportion to the elements, and factoring it whole needs its Cholesky factor's entries. A request beyond either
// is refused with the estimate in the message.
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

/// Stored entries of the Cholesky factor of that stiffness under a nested-dissection ordering, calibrated on
/// CHOLMOD's: N dofs give about 16 N^(4/3) in 3D (the 16³ cantilever: 13 855 dofs, 5.40e6) and 4.5 N log2 N in 2D
/// (the 120² cantilever: 29 039 dofs, 1.94e6).
double estimate_factor_nonzeros(double elements, int dim);

/// Issues (at `path`) for a model of `elements` elements beyond the 32-bit index limit or this machine's memory: to
/// assemble it, and when `factored_whole` (a solver that factors each body whole: not `feti` or `petsc`) to factor it.
void check_model_limits(double elements, int dim, const std::string& path, std::vector<Issue>& issues,
                        bool factored_whole = false);

}  // namespace rollsim
