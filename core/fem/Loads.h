#pragma once
// External loads of one body as nodal forces at every dof (node-major): point forces on node
// sets and consistent nodal forces of uniform pressures on surfaces.
#include <Eigen/Dense>

#include "model/Model.h"

namespace rollsim {

Eigen::VectorXd external_nodal_load(const Model& model, int body_index);

}  // namespace rollsim
