#pragma once
// External loads of one body as nodal forces at every dof (node-major): point forces on node sets and consistent
// nodal forces (∫ N t dA, ∫ N b dV by Gauss quadrature, exact for uniform loads on linear elements) of uniform
// pressures and tractions on surfaces and of body forces.
#include <Eigen/Dense>

#include "model/Model.h"

namespace rollsim {

Eigen::VectorXd external_nodal_load(const Model& model, int body_index);

/// The consistent nodal forces of one traction on `mesh` (its body's mesh), every dof.
Eigen::VectorXd traction_nodal_load(const Mesh& mesh, const Traction& traction);

}  // namespace rollsim
