#include "project/ModelLimits.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

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

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? static_cast<double>(pages) * static_cast<double>(size) : 0.0;
}

namespace {
std::string gigabytes(double bytes) {
  char s[32];
  std::snprintf(s, sizeof s, "%.1f GB", bytes / 1e9);
  return s;
}
std::string count(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", v);
  return s;
}
}  // namespace

void check_model_limits(double elements, int dim, const std::string& path, std::vector<Issue>& issues) {
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
  if (memory > 0 && e.bytes > memory)
    issues.push_back({path, count(elements) + " elements need about " + gigabytes(e.bytes) +
                                " to assemble the stiffness alone (factoring it needs more), and this machine has " +
                                gigabytes(memory)});
}

}  // namespace rollsim
