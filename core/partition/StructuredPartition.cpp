#include "partition/StructuredPartition.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollsim {

namespace {
void check_slices(const Mesh& mesh, const std::array<int, 3>& s) {
  std::vector<PartitionProblem> problems;
  for (int a = 0; a < 3; ++a)
    if (s[a] < 1)
      problems.push_back({"partition", std::string("the slice count along ") + "xyz"[a] + " must be at least 1"});
  if (mesh.dim == 2 && s[2] > 1)
    problems.push_back({"partition", "a 2D body cannot be sliced along z (" + std::to_string(s[2]) + " slices)"});
  if (!problems.empty()) throw PartitionError(problems);
}

struct Box {
  std::array<double, 3> lo, hi;
};

Box bounding_box(const Mesh& mesh) {
  Box b;
  b.lo.fill(std::numeric_limits<double>::max());
  b.hi.fill(std::numeric_limits<double>::lowest());
  for (const auto& x : mesh.nodes)
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = std::min(b.lo[a], x[a]);
      b.hi[a] = std::max(b.hi[a], x[a]);
    }
  return b;
}

int slice_of(double c, double lo, double hi, int n) {
  if (n == 1 || !(hi > lo)) return 0;
  const int i = static_cast<int>(std::floor((c - lo) / (hi - lo) * n));
  return std::clamp(i, 0, n - 1);
}
}  // namespace

Partition structured_partition(const Mesh& mesh, const std::array<int, 3>& s) {
  check_slices(mesh, s);
  const Box box = bounding_box(mesh);
  const int nn = mesh.nodes_per_elem();
  Partition p;
  p.num_subdomains = s[0] * s[1] * s[2];
  p.description = std::to_string(s[0]) + "x" + std::to_string(s[1]) + (mesh.dim == 3 ? "x" + std::to_string(s[2]) : "");
  p.element_subdomain.resize(static_cast<size_t>(mesh.num_elements()));
  for (int e = 0; e < mesh.num_elements(); ++e) {
    std::array<int, 3> idx{0, 0, 0};
    for (int a = 0; a < 3; ++a) {
      double c = 0;
      for (int k = 0; k < nn; ++k) c += mesh.nodes[mesh.element(e)[k]][a];
      idx[a] = slice_of(c / nn, box.lo[a], box.hi[a], s[a]);
    }
    p.element_subdomain[e] = idx[0] + s[0] * (idx[1] + s[1] * idx[2]);
  }
  return p;
}

}  // namespace rollsim
