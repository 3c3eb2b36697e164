#pragma once
// The subdomain interface of one body and its signed Boolean constraint blocks — paper §2: subdomains are glued
// by multipliers λ_D through signed Boolean matrices B_i, Σ_i B_i u_i = 0, each row +1 on one copy of a dof and
// −1 on another.
#include <utility>
#include <vector>

#include "base/SparseMatrix.h"
#include "mesh/Mesh.h"
#include "model/DofMap.h"
#include "partition/Partition.h"
#include "partition/Subdomain.h"

namespace rollsim {

/// Which copies of an interface dof are tied, at a node held by k subdomains:
///  NonRedundant   k − 1 pairs, a spanning tree: face-adjacent pairs first (a subdomain touching the others only
///                 at the node is tied to the lowest subdomain); B has full row rank. The paper's 2D choice.
///  FullyRedundant all k(k − 1)/2 pairs.
///  FacePairs      one pair per two subdomains sharing an edge (2D) / face (3D) through the node — every
///                 interface edge/face carries all its nodes; 4 at a 3D edge line, 12 at a 3D corner of eight.
///                 The count of the paper's 3D tables; redundant (rank k − 1 per dof) where k > 2.
enum class Multipliers { NonRedundant, FullyRedundant, FacePairs };

const char* to_string(Multipliers m);

struct InterfaceNode {
  int node = 0;                                 // body node
  std::vector<int> subdomains;                  // ascending, at least 2
  std::vector<std::pair<int, int>> face_pairs;  // (a < b) sharing a facet that contains the node, ascending
};

struct Interface {
  std::vector<InterfaceNode> nodes;  // ascending body node
  std::vector<int> multiplicity;     // per body node: subdomains holding it (0: a node of no element)
};

/// Interface of a valid partition: the nodes held by two or more subdomains.
Interface find_interface(const Mesh& mesh, const Partition& p);

/// The tied pairs (a < b; row +1 on a's copy, −1 on b's) at one interface node, each for every free component.
std::vector<std::pair<int, int>> constraint_pairs(const InterfaceNode& n, Multipliers choice);

/// Multipliers the solver gets: constraint pairs × free components (prescribed dofs are eliminated, not glued).
long count_multipliers(const Interface& iface, const DofMap& body_dofs, Multipliers choice);

/// The paper's counting (Tables VIII–XI, every row but two misprints, docs/PARTITIONS.md): every dof of an
/// interface node, prescribed ones included, times the pairs of the paper's choice — NonRedundant in 2D
/// (k − 1: 3 at a crosspoint of four), FacePairs in 3D (4 on an edge line of four subdomains, 12 at a corner).
long paper_convention_count(const Interface& iface, int dim);

/// Signed Boolean blocks B_s, one per subdomain: rows = this body's interface multipliers (node by node, pair by
/// pair, component by component), columns = the subdomain's local free dofs.
std::vector<SparseMatrix> boolean_blocks(const Interface& iface, const DofMap& body_dofs,
                                         const std::vector<Subdomain>& subs, Multipliers choice);

}  // namespace rollsim
