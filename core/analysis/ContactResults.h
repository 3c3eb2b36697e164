#pragma once
// Contact forces from the multipliers: the force on a slave node is −Cᵀλ restricted to it
// (tied rows: −λ per component; frictionless rows: −λ n).
#include <vector>

#include "analysis/Results.h"
#include "contact/ContactConstraints.h"

namespace rollsim {

/// `rows[kept[r]]` is the row of multiplier r. Fills results.contacts and every body's contact_pressure (nodal
/// f·n / tributary measure on the slave nodes, so that Σ pressure × measure over a pair is its normal_force).
void contact_results(const Model& model, const std::vector<PairState>& pairs, const std::vector<ConstraintRow>& rows,
                     const std::vector<int>& kept, const Eigen::VectorXd& lambda, Results& results);

}  // namespace rollsim
