#pragma once
// External loads of one body as nodal forces at every dof (node-major): point forces on node sets and consistent
// nodal forces (∫ N t dA, ∫ N b dV by Gauss quadrature, exact for uniform loads on linear elements) of uniform
// pressures and tractions on surfaces and of body forces; and pressures that follow the deformed surface, with their
// load stiffness.
#include <Eigen/Dense>

#include "model/Model.h"

namespace rollsim {

/// The dead loads of body `body_index` (every pressure but those that follow the surface).
Eigen::VectorXd external_nodal_load(const Model& model, int body_index);

/// A pressure [stress] that follows its surface as the body deforms: −p n da on the current surface, n its outward
/// normal — it turns with the surface and acts on its current area (a gas or a liquid's pressure).
struct FollowerPressure {
  double value = 0.0;
  std::vector<Facet> facets;  // of the mesh it is evaluated on
};

/// Body b's follower pressures, on the facets of its mesh.
std::vector<FollowerPressure> follower_pressures(const Model& model, int b);

/// The follower pressures' consistent nodal forces (every dof, node-major) on the surface moved by `u` (every node's
/// dofs, node-major).
Eigen::VectorXd follower_nodal_load(const Mesh& mesh, const std::vector<FollowerPressure>& loads,
                                    const Eigen::VectorXd& u);

/// ∂f/∂u of the nodal forces of pressure p on one facet at displacement u, in the dofs of the facet's element
/// (nodes_per_elem × dim, node-major; the element's other nodes give zero rows and columns). Not symmetric in
/// general: it is where the load depends on the motion.
Eigen::MatrixXd follower_facet_stiffness(const Mesh& mesh, const Facet& facet, double p, const Eigen::VectorXd& u);

/// The consistent nodal forces of one traction on `mesh` (its body's mesh), every dof.
Eigen::VectorXd traction_nodal_load(const Mesh& mesh, const Traction& traction);

/// ∫ N_a dA of every node a over the facets (2D: per unit thickness) in the positions X + u (u: node-major, every
/// dof; null: as meshed): each node's share of the surface, where a flux per unit area becomes a nodal one.
Eigen::VectorXd surface_node_areas(const Mesh& mesh, const std::vector<Facet>& facets,
                                   const Eigen::VectorXd* u = nullptr);

}  // namespace rollsim
