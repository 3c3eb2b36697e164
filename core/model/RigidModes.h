#pragma once
// Rigid-body modes of a body (2D: 3, 3D: 6), and which of them its prescribed displacements
// leave free — a body held by nothing else can then be named before any factorization fails.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "base/SparseMatrix.h"
#include "model/Model.h"

namespace rollsim {

/// Columns: translations x, y (, z), then rotations (2D: about z; 3D: about x, y, z), node-major rows,
/// about the body's centroid and scaled by its size so that all columns are of comparable norm. With `u` (every
/// dof, node-major): the modes of the displaced configuration X + u (a finite-strain body's tangent kernel).
Eigen::MatrixXd rigid_modes(const Mesh& mesh, const Eigen::VectorXd* u = nullptr);

/// Where rigid_modes turns its rotations and how it scales them: a mesh's centroid and its largest distance from it.
struct ModeFrame {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double size = 1;
};
ModeFrame mode_frame(const Mesh& mesh);

/// The rows of rigid_modes' columns at single dofs: row i for component `component[i]` of a node at `x.row(i)`
/// (dofs × dim), rotations about `frame.center` scaled by 1 / `frame.size` — for a subset of a body's dofs in the
/// body's own frame (a subdomain's free dofs, whose rows then agree with its neighbours' on shared dofs).
Eigen::MatrixXd rigid_mode_rows(const Eigen::MatrixXd& x, const Eigen::VectorXi& component, const ModeFrame& frame);

class DofMap;

/// Orthonormal basis of ker K restricted to the free dofs of `dofs` (rows = equation numbers): the rigid
/// motions that move no prescribed dof (geometric modes checked against the Dirichlet conditions, which is
/// exact for a connected body of solid elements — no numerical rank decision on K). 0 columns when held.
/// With `u`: in the displaced configuration, as rigid_modes.
Eigen::MatrixXd kernel_basis(const Mesh& mesh, const DofMap& dofs, const Eigen::VectorXd* u = nullptr);
/// The combinations of R's orthonormal columns that K maps to zero: |K R c| ≤ `tolerance` × K's largest diagonal
/// entry. A stressed body's finite-strain tangent turns its internal forces with a rotation (K R_rot ≠ 0): its
/// kernel among the geometric modes is the translations only, and treating the rotations as kernel would invert a
/// different tangent. An unstressed one keeps all of R. Orthonormal columns; R itself when K is not R's size.
Eigen::MatrixXd stiffness_kernel(const SparseMatrix& K, const Eigen::MatrixXd& R, double tolerance = 1e-8);

/// Names of the rigid-body motions the displacement conditions of body `b` do not prevent,
/// e.g. {"translation along y", "rotation about z"}; empty when the body is held.
std::vector<std::string> free_rigid_modes(const Model& model, int b);

}  // namespace rollsim
