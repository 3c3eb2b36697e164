#pragma once
// What the factorizations and strategies measured: plain data that the analysis copies into its Results, so that
// writers read results and never the solver objects.
#include <map>
#include <string>
#include <vector>

namespace rollsim {

struct FactorStats {
  std::string ordering;                                // e.g. "RCM", "AMD", "METIS"
  double nnz_factor = 0;                               // stored entries of L (skyline: profile incl. diagonal)
  double flops = 0;                                    // floating-point operations of one numeric factorization
  double analyze_s = 0, factorize_s = 0, solve_s = 0;  // accumulated wall times
  long factorizations = 0;
  // smallest pivot of the last factorization relative to its column's diagonal, d_j / A_jj (positive definite
  // factorizations; 0: not measured): a lower bound of λ_min / λ_max, the reciprocal of the condition number
  double min_pivot_ratio = 0;
  /// flops of every numeric factorization so far (one pattern: all cost `flops`)
  double flops_total() const { return flops * static_cast<double>(factorizations); }
};

struct SolveStats {
  std::map<std::string, long> factorizations;  // per group name
  std::map<std::string, int> ranks;            // groups spread over MPI ranks (petsc_method: mixed): each one's holder
  std::vector<double> rank_factorize_s;        // and each rank's analysis and factorization seconds so far
  long cg_iterations = 0;
  /// Interface iterations done past solver.cg_tolerance only to meet Newton's constraint check
  /// (InterfaceTolerance::at_most): what a cg_tolerance too loose for the constraints cost.
  long extra_interface_iterations = 0;
  /// The dense interface solver's columns of K⁺ solved for (InterfaceFlexibility), over all groups and solves:
  /// each about one forward and back substitution's work, done many at a time.
  long interface_columns = 0;
  int solves = 0;      // linear solves so far (the number the observer's calls carry)
  FactorStats factor;  // of the global factor (direct strategies)
  double analyze_s = 0, factorize_s = 0, solve_s = 0;
  /// flops of all numeric factorizations (every pattern, every group): over factorize_s, the factorizations' rate
  double factor_flops_total = 0;
  /// Extreme eigenvalues of the last interface solve's (preconditioned, projected) operator, estimated from its
  /// CG coefficients (mixed / feti; 0 when it took fewer than 2 iterations): λ_max / λ_min ≈ condition number.
  double cg_lambda_min = 0, cg_lambda_max = 0;
};

}  // namespace rollsim
