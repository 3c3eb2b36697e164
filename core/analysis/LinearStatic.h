#pragma once
// Linear static analysis: assemble each body's group, search contact, then for each load increment solve the block
// system with the chosen strategy (repeated while the active set of frictionless contact changes), recover
// displacements, stresses, reactions and contact forces.
#include "analysis/AnalysisError.h"
#include "analysis/IncrementOptions.h"
#include "analysis/Results.h"
#include "base/Observer.h"
#include "model/Model.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

/// `increments` (1…1000) equal proportional steps: increment i solves with every load and prescribed displacement
/// times i / N, its active-set loop starting from increment i − 1's active set; the stiffness (and every factor) is
/// the same for all. One increment is the plain linear solve. Results::increments keeps the fields of each. An
/// increment whose active set still changes after `max_active_set_iterations` solves, or returns to a set it already
/// tried, ends the run not_converged; so does an interface CG that stops short of its tolerance (Results::status).
Results run_linear_static(const Model& model, SolverStrategy& solver, AnalysisObserver* observer = nullptr,
                          int increments = 1,
                          int max_active_set_iterations = IncrementOptions{}.max_active_set_iterations);

}  // namespace rollsim
