#pragma once
// Exact comparisons of compressed sparse matrices: what decides that a cached factor, ordering or preconditioner
// still belongs to the matrix at hand (keyed to the rows themselves, not to their count).
#include "solve/Factorization.h"

namespace rollsim {

/// Same shape and the same stored positions (compressed column storage compared index by index).
bool same_pattern(const SparseMatrix& a, const SparseMatrix& b);
/// Same pattern and bit-identical values.
bool same_matrix(const SparseMatrix& a, const SparseMatrix& b);

}  // namespace rollsim
