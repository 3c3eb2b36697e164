#pragma once
// Rigid-body modes of a body (2D: 3, 3D: 6), and which of them its prescribed displacements
// leave free — a body held by nothing else can then be named before any factorization fails.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "model/Model.h"

namespace rollsim {

/// Columns: translations x, y (, z), then rotations (2D: about z; 3D: about x, y, z), node-major rows,
/// about the body's centroid and scaled by its size so that all columns are of comparable norm.
Eigen::MatrixXd rigid_modes(const Mesh& mesh);

/// Names of the rigid-body motions the displacement conditions of body `b` do not prevent,
/// e.g. {"translation along y", "rotation about z"}; empty when the body is held.
std::vector<std::string> free_rigid_modes(const Model& model, int b);

}  // namespace rollsim
