#pragma once
// Strategy "mixed" (the paper's method, eqs. (2)-(3) and (7)-(8)): each group factored on its own, the
// multipliers found by (projected) CG on the condensed interface without forming it — each product F p is,
// per group, p → C_gᵀp → K_g⁺ (forward/back substitution) → C_g(·) — and the displacements recovered by
// u_g = K_g⁺(f_g − C_gᵀλ) + R_g α_g. A group is refactored only when its stiffness changed (Group::version).
#include "solve/GroupSolver.h"
#include "solve/ProjectedCG.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

class MixedStrategy final : public SolverStrategy {
 public:
  MixedStrategy(SolverOptions options, std::string factorization = "cholmod");
  BlockSolution solve(const BlockSystem& system, AnalysisObserver* observer = nullptr) override;
  const SolveStats& stats() const override { return stats_; }
  /// The last interface solve (residual history, constraint error), for tests and reports.
  const ProjectedCGResult& last_interface_solve() const { return last_; }

 private:
  void factorize_changed(const BlockSystem& sys);
  InterfaceProblem interface_problem(const BlockSystem& sys, const std::vector<Eigen::VectorXd>& Kf);

  SolverOptions options_;
  std::string kind_;
  std::vector<GroupSolver> groups_;
  std::vector<long> factored_version_;
  ProjectedCGResult last_;
  SolveStats stats_;
};

}  // namespace rollsim
