#include "bench/MeshDistortion.h"

#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace rollsim::bench {

namespace {

/// Corner pairs of the edges of a Q4 or an H8 (local numbering of mesh/Mesh.h).
std::vector<std::pair<int, int>> element_edges(ElementType t) {
  if (t == ElementType::Quad4) return {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
}

std::vector<double> shortest_incident_edge(const Mesh& mesh) {
  std::vector<double> h(mesh.nodes.size(), std::numeric_limits<double>::infinity());
  const auto edges = element_edges(mesh.type);
  for (int e = 0; e < mesh.num_elements(); ++e)
    for (const auto& [i, j] : edges) {
      const int a = mesh.element(e)[i], b = mesh.element(e)[j];
      double d = 0;
      for (int k = 0; k < 3; ++k) d += (mesh.nodes[a][k] - mesh.nodes[b][k]) * (mesh.nodes[a][k] - mesh.nodes[b][k]);
      h[a] = std::min(h[a], std::sqrt(d));
      h[b] = std::min(h[b], std::sqrt(d));
    }
  return h;
}

}  // namespace

void distort_interior_nodes(Mesh& mesh, double fraction, unsigned seed) {
  std::vector<char> fixed(mesh.nodes.size(), 0);
  for (const auto& [name, nodes] : mesh.node_sets)
    if (name != "all")
      for (int n : nodes) fixed[n] = 1;
  const std::vector<double> h = shortest_incident_edge(mesh);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (fixed[n] || !std::isfinite(h[n])) continue;
    for (int k = 0; k < mesh.dim; ++k) mesh.nodes[n][k] += fraction * h[n] * unit(rng);
  }
}

}  // namespace rollsim::bench
