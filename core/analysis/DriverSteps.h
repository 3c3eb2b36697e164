#pragma once
// The steps every analysis driver takes around a linear solve (the linear driver and the Newton driver share them):
// the load factor of an increment, a solve whose singularity is reported in the model's terms, the check that
// contact holds every floating group, and the way back from group solutions to the bodies' displacements.
#include <memory>
#include <vector>

#include "analysis/AnalysisError.h"
#include "base/Observer.h"
#include "model/DofMap.h"
#include "model/Model.h"
#include "partition/Interface.h"
#include "solve/BlockSystem.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

/// Load factor of increment i of n: i / n, exactly 1 for the last.
double load_factor(int i, int n);

/// solver.solve(sys), with a singular matrix or an unusable option reported as AnalysisError naming what is not held
/// (body, node and component when the groups are the bodies).
BlockSolution solve_checked(const Model& model, const std::vector<std::unique_ptr<DofMap>>& dofs,
                            SolverStrategy& solver, const BlockSystem& sys, AnalysisObserver& obs);

/// Every dof of every body (node-major) from the bodies' free dofs, prescribed values times `load_factor`.
std::vector<Eigen::VectorXd> full_displacements(const std::vector<std::unique_ptr<DofMap>>& dofs,
                                                const std::vector<Eigen::VectorXd>& free, double load_factor);

/// True when a contact pair is unilateral (an active set to settle): frictionless, sticking or Coulomb.
bool has_unilateral(const Model& model);

/// Throws AnalysisError when a rigid mode of a floating group moves no constrained dof (G = [C_g R_g] rank-deficient).
void check_floating_groups_held(const BlockSystem& sys);

/// The interface multipliers a strategy's options ask for.
Multipliers multiplier_choice(const SolverOptions& o);

}  // namespace rollsim
