#include "mesh/Mesh.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace rollsim {

std::vector<int> facet_local_nodes(ElementType t, int local) {
  if (t == ElementType::Quad4) {
    // counter-clockwise element: edge k runs from node k to node k+1, outward normal to its right
    static const int edges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    return {edges[local][0], edges[local][1]};
  }
  // H8 with bottom 0-1-2-3 (counter-clockwise seen from +z) and top 4-5-6-7; outward normals
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  return {faces[local][0], faces[local][1], faces[local][2], faces[local][3]};
}

std::vector<int> surface_nodes(const Mesh& mesh, const std::vector<Facet>& facets) {
  std::vector<int> ids;
  for (const Facet& f : facets) {
    const int* conn = mesh.element(f.element);
    for (int l : facet_local_nodes(mesh.type, f.local)) ids.push_back(conn[l]);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

void add_derived_node_sets(Mesh& mesh) {
  for (const auto& [name, facets] : mesh.surfaces)
    if (!mesh.node_sets.count(name)) mesh.node_sets[name] = surface_nodes(mesh, facets);
  std::vector<int> every(mesh.nodes.size());
  std::iota(every.begin(), every.end(), 0);
  mesh.node_sets["all"] = std::move(every);
}

namespace {
double corner_jacobian(const Mesh& m, const int* conn, int corner) {
  auto d = [&](int a, int b, int k) { return m.nodes[conn[b]][k] - m.nodes[conn[a]][k]; };
  if (m.type == ElementType::Quad4) {
    const int next = (corner + 1) % 4, prev = (corner + 3) % 4;
    return d(corner, next, 0) * d(corner, prev, 1) - d(corner, next, 1) * d(corner, prev, 0);
  }
  static const int nb[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  const int a = nb[corner][0], b = nb[corner][1], c = nb[corner][2];
  const double ax = d(corner, a, 0), ay = d(corner, a, 1), az = d(corner, a, 2);
  const double bx = d(corner, b, 0), by = d(corner, b, 1), bz = d(corner, b, 2);
  const double cx = d(corner, c, 0), cy = d(corner, c, 1), cz = d(corner, c, 2);
  return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}
}  // namespace

void check_element_orientation(const Mesh& mesh) {
  const int corners = mesh.nodes_per_elem();
  for (int e = 0; e < mesh.num_elements(); ++e)
    for (int c = 0; c < corners; ++c)
      if (!(corner_jacobian(mesh, mesh.element(e), c) > 0.0))
        throw std::runtime_error("element " + std::to_string(e) + " is inverted or degenerate at corner " +
                                 std::to_string(c));
}

}  // namespace rollsim
