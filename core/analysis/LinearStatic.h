#pragma once
// Linear static analysis: assemble each body's group, solve the block system with the chosen
// strategy, recover displacements, stresses and reactions.
#include <stdexcept>

#include "analysis/Observer.h"
#include "analysis/Results.h"
#include "model/Model.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

/// The model cannot be solved because a body is free to move (bad input, reported to the user).
struct UnsupportedBody : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Results run_linear_static(const Model& model, SolverStrategy& solver, AnalysisObserver* observer = nullptr);

}  // namespace rollsim
