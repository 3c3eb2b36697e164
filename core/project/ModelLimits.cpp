#include "project/ModelLimits.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "base/Memory.h"

namespace rollsim {

StiffnessEstimate estimate_stiffness(double elements, int dim) {
  const double per_node = std::pow(3.0, dim) * dim * dim;  // dofs coupled to one node's dofs × its dofs
  const double element_dofs = dim * std::pow(2.0, dim);    // 8 (Q4) or 24 (H8)
  const double nodes = elements;                           // structured: (n + 1)^dim ≈ n^dim for large n
  StiffnessEstimate e;
  e.nonzeros = nodes * per_node;
  e.bytes = elements * element_dofs * element_dofs * sizeof(int)  // scatter map: a value slot per element entry
            + nodes * std::pow(3.0, dim) * sizeof(int)            // node graph
            + e.nonzeros * (sizeof(int) + 2 * sizeof(double));    // pattern; K and the group's copy
  return e;
}

double estimate_factor_nonzeros(double elements, int dim) {
  const double dofs = elements * dim;  // structured: about one node per element
  if (dofs < 2) return dofs;
  return dim == 3 ? 16 * std::pow(dofs, 4.0 / 3.0) : 4.5 * dofs * std::log2(dofs);
}

namespace {
std::string count(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", v);
  return s;
}
}  // namespace

void check_model_limits(double elements, int dim, const std::string& path, std::vector<Issue>& issues,
                        bool factored_whole) {
  const StiffnessEstimate e = estimate_stiffness(elements, dim);
  const double index_limit = std::numeric_limits<int>::max();
  if (e.nonzeros > index_limit) {
    issues.push_back({path, count(elements) + " elements give a stiffness matrix of about " + count(e.nonzeros) +
                                " nonzeros, beyond the 32-bit sparse index limit (" + count(index_limit) +
                                "): at most about " + count(elements * index_limit / e.nonzeros) + " elements in " +
                                std::to_string(dim) + "D"});
    return;
  }
  const double memory = physical_memory_bytes();
  if (memory > 0 && e.bytes > memory) {
    issues.push_back({path, count(elements) + " elements need about " + gigabytes(e.bytes) +
                                " to assemble the stiffness alone (factoring it needs more), and this machine has " +
                                gigabytes(memory)});
    return;
  }
  const double factor = estimate_factor_nonzeros(elements, dim) * sizeof(double);
  if (factored_whole && memory > 0 && e.bytes + factor > memory)
    issues.push_back({path, count(elements) + " elements need about " + gigabytes(e.bytes + factor) +
                                " to assemble and factor the stiffness (its Cholesky factor about " +
                                count(factor / sizeof(double)) +
                                " entries, a nested-dissection estimate), and this "
                                "machine has " +
                                gigabytes(memory) +
                                ": a coarser mesh, or `feti` with subdomains (each factored on its own)"});
}

}  // namespace rollsim
