#pragma once
// Reverse Cuthill-McKee ordering (George-Liu pseudo-peripheral roots) and skyline profile measures.
#include <vector>

#include "solve/Factorization.h"

namespace rollsim {

/// Permutation `perm` of the graph of A (square, both triangles stored): new position k holds old index perm[k].
/// Each connected component is ordered in turn from a George-Liu pseudo-peripheral node, neighbours by increasing
/// degree, and the whole order is reversed. The last `trailing` rows/cols (e.g. Lagrange multipliers) stay last, in
/// their original order, and are ignored by the ordering of the others.
std::vector<int> reverse_cuthill_mckee(const SparseMatrix& A, int trailing = 0);

/// first[j] = smallest row index of a non-zero in column j of the upper triangle of P A P^T (first[j] <= j).
std::vector<int> skyline_first_rows(const SparseMatrix& A, const std::vector<int>& perm);

/// Sum of the column heights (first non-zero row to the diagonal, both included) of the upper triangle of P A P^T.
long profile_size(const SparseMatrix& A, const std::vector<int>& perm);

}  // namespace rollsim
