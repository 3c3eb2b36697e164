#pragma once
// From a validated project to the model: cross-reference checks (names, sets, sizes) before
// anything is allocated, then mesh generation, node sets, boundary conditions and probes.
#include <string>
#include <vector>

#include "model/Model.h"
#include "project/Project.h"

namespace rollsim {

/// Checks names, references, generator parameters and model size; appends problems to `issues`.
void check_references(const Project& project, std::vector<Issue>& issues);

/// Why a project (its process expanded) needs the Newton analysis ("" if it does not): a plastic material, finite
/// kinematics or friction.
std::string nonlinear_because(const json& expanded_project);

/// Builds the model. Throws ProjectError for problems only visible on the mesh (inverted elements).
Model build_model(const Project& project);

}  // namespace rollsim
