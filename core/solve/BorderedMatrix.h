#pragma once
// Paper eq. (1) as one matrix: the groups' K on the diagonal, the independent constraint rows C below them and C_eqᵀ
// beside them, multipliers last — what `direct` factors whole and `petsc`'s mumps method hands to MUMPS in pieces
// (each MPI rank its own groups' K, rank 0 the border).
#include <Eigen/Sparse>
#include <vector>

#include "solve/BlockSystem.h"

namespace rollsim {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

/// The entries of the bordered matrix: the K of every group `stiffness` marks (empty: every group), and when `border`
/// the rows `kept` of C (row n + i for kept[i]), C_eqᵀ (unsymmetric under Coulomb slip) and the coupling stiffness.
/// Groups sit one after the other by their C's columns (a group another process assembles has no K here).
Triplets bordered_entries(const BlockSystem& sys, const std::vector<int>& kept, const std::vector<char>& stiffness,
                          bool border);

/// The whole bordered matrix of `sys` with the constraint rows `kept`: (n + kept) × (n + kept).
SparseMatrix bordered_matrix(const BlockSystem& sys, const std::vector<int>& kept);

/// What a factor of the bordered matrix was made from — every group's stiffness version and constraint blocks, and the
/// coupling stiffness: the factor still belongs to a system exactly when all of them are the same (`direct` and
/// `petsc`'s mumps refactor then, and only then).
class BorderedFactorKey {
 public:
  bool matches(const BlockSystem& sys) const;
  void record(const BlockSystem& sys);
  void clear() { versions_.clear(); }

 private:
  std::vector<long> versions_;  // empty: nothing recorded
  std::vector<SparseMatrix> C_, C_eq_;
  SparseMatrix coupling_;
};

/// Refuses a solve whose normwise backward error ‖A x − f‖∞ / (‖A‖∞ ‖x‖∞ + ‖f‖∞) is above 1e-8 (round-off is ~1e-16
/// for a stable factorization of a regular matrix): SingularMatrix — the factor does not represent A, a pivot lost
/// to cancellation that the factorization's own tests let through (UMFPACK and MUMPS stop only at a zero pivot).
void check_backward_error(double error);

}  // namespace rollsim
