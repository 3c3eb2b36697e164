#pragma once
// Strategy "mixed" (the paper's method, eqs. (2)-(3) and (7)-(8)): each group factored on its own, the
// multipliers found by (projected) CG on the condensed interface without forming it — each product F p is,
// per group, p → C_gᵀp → K_g⁺ (forward/back substitution) → C_g(·) — and the displacements recovered by
// u_g = K_g⁺(f_g − C_gᵀλ) + R_g α_g. A group is refactored only when its stiffness changed (Group::version).
// Spread over processes (a GroupDistribution: `petsc` with `petsc_method: mixed`), each process factors and solves
// with the groups it holds, the interface vectors and every group's kernel and displacement are summed over the
// processes, and every process runs the same interface Krylov solve.
#include <functional>

#include <memory>

#include "solve/ConstraintBasis.h"
#include "solve/GroupDistribution.h"
#include "solve/GroupSolver.h"
#include "solve/InterfaceFlexibility.h"
#include "solve/InterfacePreconditioner.h"
#include "solve/ProjectedCG.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

class MixedStrategy final : public SolverStrategy {
 public:
  /// `subdomains`: the `feti` flavour (partitioned bodies torn into subdomains, preconditioner from the options).
  /// `spread`: the groups over processes (null: this process holds them all); spread, the dense interface solver and
  /// the preconditioner-weighted projector are refused (std::invalid_argument) — they are not distributed yet.
  MixedStrategy(SolverOptions options, bool subdomains = false, std::string factorization = "cholmod",
                std::shared_ptr<const GroupDistribution> spread = nullptr);
  BlockSolution solve(const BlockSystem& system, AnalysisObserver* observer = nullptr) override;
  const SolveStats& stats() const override { return stats_; }
  bool uses_subdomains() const override { return subdomains_; }
  const SolverOptions& options() const override { return options_; }
  /// The groups this process holds (all of them unless spread).
  std::vector<size_t> local_groups(std::vector<size_t> groups) const override;
  /// A group with C_eq (slipping Coulomb friction) makes the interface unsymmetric: projected GMRES solves it.
  bool solves_unsymmetric() const override { return true; }
  /// `mixed` (not `feti`): compliant rows join its interface, each multiplier with its compliance on F's diagonal.
  bool solves_compliant() const override { return !subdomains_; }
  /// λ is as accurate as the last interface CG's relative tolerance (dense: exact, as `direct`'s)
  double multiplier_tolerance() const override {
    return options_.interface_solver == InterfaceSolver::Dense ? SolverStrategy::multiplier_tolerance()
                                                               : last_tolerance_;
  }
  /// The last interface solve (residual history, constraint error), for tests and reports.
  const ProjectedCGResult& last_interface_solve() const { return last_; }
  /// Interface solves done by projected GMRES: an unsymmetric F (friction), or an indefinite group factor.
  long gmres_solves() const { return gmres_solves_; }

 private:
  void factorize_changed(const BlockSystem& sys, AnalysisObserver* observer);
  /// The solve of a system without compliant rows (solve() adds them to the interface first).
  BlockSolution solve_plain(const BlockSystem& system, AnalysisObserver* observer);
  InterfaceProblem interface_problem(const BlockSystem& sys, const std::vector<Eigen::VectorXd>& Kf);
  /// F = Σ_g C_g K_g⁺ C_eq,gᵀ formed (the `dense` interface solver), each group's part concurrently
  Eigen::MatrixXd formed_interface(const BlockSystem& sys);
  /// The interface solve: dense, or projected CG / GMRES (with the preconditioner, when there is one)
  /// The Krylov solve's options: the system's interface tolerance where it sets one, else solver.cg_tolerance
  /// (kept as the multipliers' accuracy).
  ProjectedCGOptions krylov_options(const BlockSystem& sys, int solve);
  ProjectedCGResult solve_interface(const BlockSystem& sys, InterfaceProblem& problem, bool new_preconditioner,
                                    int solve, AnalysisObserver* observer);

  /// y = Σ_g C_g op(g) over the groups with constraints: op(g) (a vector on group g's free dofs) concurrently on
  /// options_.threads threads, the products with the sparse C_g added in group order, so the result is
  /// bit-identical for any thread count (and no dense multiplier-length vector is made per group).
  Eigen::VectorXd sum_over_groups(const BlockSystem& sys, const std::function<Eigen::VectorXd(size_t)>& op) const;
  /// Q G = M⁻¹ G for the weighted projector, kept while neither the preconditioner nor G changes (Newton
  /// iterations and active-set passes that refactor nothing reuse it).
  /// True when every group's constraint block is the one in `C` (an active set that swaps rows while keeping their
  /// count is a change): the preconditioner's, or the dense solver's independent rows'.
  static bool same_constraints(const BlockSystem& sys, const std::vector<SparseMatrix>& C);
  /// Some group's factor is of an indefinite tangent (GroupSolver::indefinite): the interface is solved by GMRES.
  bool any_indefinite() const;
  bool held(size_t g) const { return !spread_ || spread_->holds(g); }
  /// Spread: x summed over the processes (a no-op in one process).
  void sum(Eigen::VectorXd& x) const {
    if (spread_) spread_->sum(x);
  }
  /// Group g's kernel R_g as its holder has it (a finite-strain group's R is the kernel of the tangent it assembled):
  /// spread, shared (shared_kernels) at the start of each solve.
  const Eigen::MatrixXd& kernel(const BlockSystem& sys, size_t g) const {
    return spread_ ? kernels_[g] : sys.groups[g].R;
  }
  const SparseMatrix& weighted_modes(const BlockSystem& sys, const SparseMatrix& G, bool preconditioner_changed);

  SolverOptions options_;
  bool subdomains_;
  std::shared_ptr<const GroupDistribution> spread_;
  std::vector<Eigen::MatrixXd> kernels_;  // spread: every group's R from its holder
  std::unique_ptr<InterfacePreconditioner> preconditioner_;
  std::vector<SparseMatrix> preconditioned_C_;  // every group's C when the preconditioner was set up
  SparseMatrix QG_, QG_of_;                     // weighted_modes() and the G it was computed for
  std::string kind_;
  std::vector<GroupSolver> groups_;
  std::vector<InterfaceFlexibility> flexibility_;  // per group, for the dense interface solver
  ConstraintBasis basis_;                          // dense: the independent constraint rows …
  std::vector<SparseMatrix> basis_C_;              // … of these constraint blocks
  std::vector<long> factored_version_;
  ProjectedCGResult last_;
  long gmres_solves_ = 0;
  double last_tolerance_ = options_.cg_tolerance;  // the relative tolerance of the last interface solve
  SolveStats stats_;
};

}  // namespace rollsim
