#pragma once
// The independent rows of a constraint block C and the null space of Cᵀ. Contact rows can be linearly dependent:
// where a slave node's dofs are prescribed (a symmetry plane), its stick rows hold only master dofs, and more slave
// nodes than master nodes along such a line give more rows than the dofs they hold (the 3D pass on 24 × 12 × 8:
// four axial stick rows on three roll dofs). The interface CG of `mixed` tolerates that (its λ stays in range C);
// the bordered matrix [K Cᵀ; C 0] is then singular, and with round-off terms (1e-17) left in the rows an LU factors
// it with pivots of that size: λ of 1e40 and a correction that is no solution. `direct` keeps the independent rows.
#include <vector>

#include "solve/BlockSystem.h"

namespace rollsim {

struct ConstraintBasis {
  std::vector<int> kept;       // a maximal set of independent rows of C, ascending
  Eigen::MatrixXd null_space;  // rows of C × dependent rows: a basis of ker Cᵀ (no columns when C has full row rank)

  bool full_rank() const { return null_space.cols() == 0; }
  /// λ − N(NᵀN)⁻¹Nᵀλ: the multipliers of least norm with the same forces Cᵀλ (those the interface CG finds from a
  /// start in range C), so that every strategy reports the same λ for dependent rows.
  Eigen::VectorXd minimum_norm(const Eigen::VectorXd& lambda) const;
  /// Every one of `rows` multipliers from the kept rows' (kept_lambda[i] of row kept[i]): 0 on the dependent rows,
  /// then the least-norm λ with the same forces.
  Eigen::VectorXd every_row(const Eigen::VectorXd& kept_lambda, long rows) const;
};

/// The rows of C (multipliers × dofs) that are independent to a relative tolerance: a row whose part orthogonal to
/// the rows kept before it is below 1e-10 of the largest row norm is dependent (rank-revealing sparse QR of Cᵀ).
ConstraintBasis independent_rows(const SparseMatrix& C);

/// The rows left out as dependent hold too: C_j u = d_j to round-off of its terms (see the .cpp); otherwise they
/// contradict the rows they depend on and no solution exists — SingularMatrix naming the row and its miss.
void check_dependent_rows(const BlockSystem& sys, const ConstraintBasis& basis, const std::vector<Eigen::VectorXd>& u);

/// Every group's C side by side: the multipliers × all dofs.
SparseMatrix stacked_constraints(const BlockSystem& sys);

}  // namespace rollsim
