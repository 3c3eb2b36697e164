#pragma once
// From a validated project to the model: cross-reference checks (names, sets, sizes) before
// anything is allocated, then mesh generation, node sets, boundary conditions and probes.
#include <string>
#include <vector>

#include "analysis/NewtonStatic.h"
#include "model/Model.h"
#include "project/Project.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

/// Checks names, references, generator parameters and model size; appends problems to `issues`.
void check_references(const Project& project, std::vector<Issue>& issues);

/// The solver section as strategy options (validated values).
SolverOptions solver_options(const Project& project);

/// analysis.increments: the load increments of the run (validated, 1 by default).
int load_increments(const Project& project);
/// analysis.type as run: `auto` (the default) is newton when a material has a yield stress, else linear.
std::string analysis_type(const Project& project);
/// The Newton driver's settings: analysis.increments, max_iterations, tolerance, max_cutbacks.
NewtonOptions newton_options(const Project& project);
/// analysis.max_active_set_iterations (1…1000; 50 when absent).
int max_active_set_iterations(const Project& project);

/// Builds the model. Throws ProjectError for problems only visible on the mesh (inverted elements).
Model build_model(const Project& project);

}  // namespace rollsim
