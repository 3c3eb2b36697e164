#pragma once
// Helpers of the tests that build their projects as JSON: validate one (its refusal), run one in process, and read the
// reaction of a set whose nodes were all moved to the same prescribed y displacement.
#include <Eigen/Dense>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace testing_support {

/// What validating the project `j` says: the ProjectError's message, or "accepted".
inline std::string refusal_of(const nlohmann::json& j) {
  try {
    rollsim::parse_project(j.dump(), "test.json");
  } catch (const rollsim::ProjectError& e) {
    return e.what();
  }
  return "accepted";
}

/// The project `j` validated, built and run (run_project: the analysis its `analysis.type` names).
inline rollsim::Results run_json(const nlohmann::json& j) {
  const rollsim::Project p = rollsim::parse_project(j.dump(), "test.json");
  return rollsim::run_project(p, rollsim::build_model(p), nullptr);
}

/// Σ of component k of the nodal forces of body `b` over its nodes whose y displacement is `uy` (a set prescribed
/// to it): the force the prescribed set carries.
inline double reaction_where_uy(const rollsim::Results& r, size_t b, int dim, double uy, int k) {
  const Eigen::VectorXd &f = r.bodies[b].nodal_force, &u = r.bodies[b].displacement;
  double s = 0;
  for (Eigen::Index n = 0; n < u.size() / dim; ++n)
    if (std::abs(u[dim * n + 1] - uy) < 1e-12) s += f[dim * n + k];
  return s;
}

}  // namespace testing_support
