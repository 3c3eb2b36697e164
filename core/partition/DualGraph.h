#pragma once
// The element dual graph over shared facets (Q4: an edge, H8: a face). Facet sharing is the mechanical
// connection: two elements touching only at a node (or, in 3D, along an edge) form a hinge, so a subdomain
// is "connected" — and has exactly the rigid-body kernel — only through shared facets.
#include <array>
#include <vector>

#include "mesh/Mesh.h"

namespace rollsim {

/// Elements a < b sharing one facet, and the facet's body nodes (2 in 2D, 4 in 3D).
struct SharedFacet {
  int a = 0, b = 0;
  std::array<int, 4> nodes{-1, -1, -1, -1};
  int num_nodes = 0;
};

/// Every pair of elements sharing a facet, sorted by (a, b).
std::vector<SharedFacet> shared_facets(const Mesh& mesh);

/// Compressed adjacency (METIS layout): neighbours of element e are adjncy[xadj[e] .. xadj[e + 1]), ascending.
struct DualGraph {
  std::vector<int> xadj, adjncy;
};
DualGraph dual_graph(int num_elements, const std::vector<SharedFacet>& facets);

/// Connected component (0, 1, ... in order of first element) of every element; with `group`, only facets
/// between elements of the same group join them (the pieces of each subdomain).
std::vector<int> connected_components(int num_elements, const std::vector<SharedFacet>& facets,
                                      const std::vector<int>* group = nullptr);

}  // namespace rollsim
