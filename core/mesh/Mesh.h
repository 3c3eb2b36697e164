#pragma once
// Unstructured mesh of one body: nodes, linear elements (Q4 in 2D, H8 in 3D),
// named node sets, element sets and surfaces (element faces / edges).
#include <array>
#include <map>
#include <string>
#include <vector>

namespace rollsim {

enum class ElementType { Quad4, Hex8 };

inline int nodes_per_element(ElementType t) { return t == ElementType::Quad4 ? 4 : 8; }
inline int dimension_of(ElementType t) { return t == ElementType::Quad4 ? 2 : 3; }

/// One face of an element: an edge of a Q4 (local 0..3) or a face of an H8 (local 0..5).
struct Facet {
  int element;
  int local;
};

struct Mesh {
  int dim = 2;
  ElementType type = ElementType::Quad4;
  std::vector<std::array<double, 3>> nodes;  // z = 0 in 2D
  std::vector<int> connectivity;             // nodes_per_element() per element
  std::map<std::string, std::vector<int>> node_sets;
  std::map<std::string, std::vector<int>> element_sets;
  std::map<std::string, std::vector<Facet>> surfaces;

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int nodes_per_elem() const { return nodes_per_element(type); }
  int num_elements() const { return static_cast<int>(connectivity.size()) / nodes_per_elem(); }
  const int* element(int e) const { return connectivity.data() + e * nodes_per_elem(); }
};

/// Local node numbers of facet `local` of an element (2 nodes for Q4, 4 for H8),
/// ordered so that the outward normal follows the right-hand rule (3D) or lies to the right of the edge (2D).
std::vector<int> facet_local_nodes(ElementType t, int local);

/// Node ids touched by a surface, sorted and unique.
std::vector<int> surface_nodes(const Mesh& mesh, const std::vector<Facet>& facets);

/// Adds the node sets every generator provides: one per surface that has no node set of the same
/// name, and "all" (every node).
void add_derived_node_sets(Mesh& mesh);

/// Throws std::runtime_error naming the element if any element has non-positive Jacobian at a corner.
void check_element_orientation(const Mesh& mesh);

}  // namespace rollsim
