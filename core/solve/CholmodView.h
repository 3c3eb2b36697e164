#pragma once
// Eigen ↔ CHOLMOD without copies: a cholmod_sparse header over a compressed Eigen matrix, and a dense solve with
// any CHOLMOD factor (the simplicial LDLᵀ of the benchmarks; CholmodFactorization solves through SupernodalSolve).
#include <cholmod.h>

#include "solve/Factorization.h"

namespace rollsim {

/// The header of A for CHOLMOD (A must be compressed: throws std::invalid_argument otherwise). `stype` as
/// CHOLMOD's: −1 symmetric, lower triangle read; 1 symmetric, upper triangle read; 0 unsymmetric. The default reads
/// the upper triangle of a matrix that stores both: cholmod_factorize then forms tril(PAPᵀ) with one transpose instead
/// of the two a lower triangle costs (the 32 × 16 × 8 cube: one factorization 2.6 ms faster).
cholmod_sparse cholmod_view(const SparseMatrix& A, int stype = 1);

/// x = A⁻¹ b with cholmod_solve and the factor L of A.
Eigen::VectorXd cholmod_solve_vector(cholmod_factor& L, const Eigen::VectorXd& b, cholmod_common& common);

}  // namespace rollsim
