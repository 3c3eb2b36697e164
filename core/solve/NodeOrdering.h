#pragma once
// Fill-reducing ordering of a finite-element matrix on its node graph: the columns that belong to one node (2 or 3
// in a row, with identical sparsity patterns) are merged into one vertex, the smaller graph is ordered by METIS
// nested dissection, and each vertex is expanded back to its columns, kept together. The graph is 2-3× smaller
// than the dof graph (9× fewer edges in 3D), so the ordering is cheaper, and a node's columns stay adjacent, so the
// factor's supernodes never split a node.
#include <vector>

#include "solve/Factorization.h"

namespace rollsim {

/// Supervariables: runs of consecutive columns with the same sparsity pattern. Returns the first column of every run
/// and, last, A.cols() (so run r is [first[r], first[r + 1])).
std::vector<int> column_runs(const SparseMatrix& A);

/// Mean number of nodes (runs) coupled to a node, itself included: 9 for bilinear quadrilaterals, 27 for trilinear
/// hexahedra — which of the two regimes of fill a mesh is in.
double mean_node_degree(const SparseMatrix& A);

/// METIS_NodeND on the graph of the runs of A (both triangles stored), expanded to a permutation of A's columns:
/// perm[k] = the column eliminated k-th. Deterministic (METIS seed fixed). Not thread-safe (METIS's random state is
/// process-wide): callers serialize it, as CholmodFactorization does.
std::vector<int> node_nested_dissection(const SparseMatrix& A);

}  // namespace rollsim
