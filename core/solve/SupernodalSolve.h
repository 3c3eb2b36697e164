#pragma once
// x = A⁻¹ b with a CHOLMOD supernodal LLᵀ factor of A (P A Pᵀ = L Lᵀ), the triangular solves written with Eigen's
// dense kernels on each supernode's block instead of cholmod_solve.
//
// Why: cholmod_solve does one BLAS dtrsv and one dgemv per supernode. OpenBLAS 0.3.21 (Debian 12) takes a
// process-wide lock to hand out a work buffer inside every level-2 call, so with FETI's many small subdomain
// factors (2D: supernodes of a few columns) the lock and the call overhead cost more than the arithmetic, and two
// threads solving different subdomains at once serialise on it: `feti --threads 2` was no faster than 1 thread on
// the 2D cantilevers (docs/BENCHMARKS-FETI.md §4). Eigen's kernels are inlined, allocate nothing and share nothing.
#include <cholmod.h>

#include <Eigen/Core>

namespace rollsim {

/// `L` is a numeric supernodal LLᵀ factor with int indices (cholmod_factorize with CHOLMOD_SUPERNODAL);
/// `work` is resized as needed and may be reused between calls (one per thread).
Eigen::VectorXd supernodal_solve(const cholmod_factor& L, const Eigen::VectorXd& b, Eigen::VectorXd& work);

/// Eᵀ A⁻¹ E = WᵀW with W = L⁻¹ P E, for an E of few nonzeros per column (unit columns: a flexibility's dofs). A
/// column of W is nonzero only on the supernodes above its nonzeros in the supernodal elimination tree, so each
/// supernode's triangular solve and update take only the columns that reach it, and WᵀW is summed supernode by
/// supernode over them. The saving is the share of (supernode, column) pairs outside the reaches: near the leaves
/// of a nested dissection, where surface dofs start.
Eigen::MatrixXd supernodal_inverse_quadratic(const cholmod_factor& L, const Eigen::MatrixXd& E);

}  // namespace rollsim
