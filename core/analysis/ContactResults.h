#pragma once
// Contact forces from the multipliers: the force on a slave node is −Cᵀλ restricted to it
// (tied rows: −λ per component; frictionless rows: −λ n).
#include <memory>
#include <vector>

#include "analysis/Results.h"
#include "contact/ContactConstraints.h"
#include "model/DofMap.h"

namespace rollsim {

/// `rows[kept[r]]` is the row of multiplier r. Fills results.contacts and every body's contact_pressure (nodal
/// f·n / tributary measure on the slave nodes, so that Σ pressure × measure over a pair is its normal_force).
void contact_results(const Model& model, const std::vector<PairState>& pairs, const std::vector<ConstraintRow>& rows,
                     const std::vector<int>& kept, const Eigen::VectorXd& lambda, Results& results);

/// The contact forces on supported dofs join their reactions (a rigid, driven master such as a rigid roll): a row's
/// term on a prescribed dof adds λ × its coefficient to that dof's nodal_force, and the friction force of slipping
/// points on it (`friction`: per body, every dof, node-major; empty: none) is taken off — the reaction is internal −
/// external + Cᵀλ − friction there.
void add_contact_reactions(const std::vector<std::unique_ptr<DofMap>>& dofs, const std::vector<ConstraintRow>& rows,
                           const std::vector<int>& kept, const Eigen::VectorXd& lambda,
                           const std::vector<Eigen::VectorXd>& friction, Results& results);

}  // namespace rollsim
