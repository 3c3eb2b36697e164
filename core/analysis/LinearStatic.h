#pragma once
// Linear static analysis: assemble each body's group, search contact, solve the block system with the chosen
// strategy (repeated while the active set of frictionless contact changes), recover displacements, stresses,
// reactions and contact forces.
#include <stdexcept>

#include "analysis/Observer.h"
#include "analysis/Results.h"
#include "model/Model.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

/// The model cannot be solved as given (a body free to move, contact that cannot hold a floating body, a strategy
/// that cannot handle the model): bad input, reported to the user with exit code 2.
struct AnalysisError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Results run_linear_static(const Model& model, SolverStrategy& solver, AnalysisObserver* observer = nullptr);

}  // namespace rollsim
