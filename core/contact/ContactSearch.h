#pragma once
// Contact search in the undeformed configuration: each slave node is projected on the master surface
// (node-to-segment in 2D, node-to-face on bilinear faces in 3D); the projection gives the master nodes,
// their interpolation weights, the master's outward normal and the initial gap.
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "mesh/Mesh.h"

namespace rollsim {

struct ContactPoint {
  int slave_node = 0;
  std::vector<int> master_nodes;    // nodes of the master facet holding the projection
  std::vector<double> N;            // their shape function values at the projection (sum 1)
  Eigen::Vector3d normal{0, 0, 0};  // master outward unit normal at the projection (points towards the slave)
  double gap = 0;     // normal · (x_slave − x_projection) − offset: > 0 open, < 0 penetrating [length]
  double offset = 0;  // how far the master's true surface lies outside the facet, along the normal [length]
  double weight = 0;  // tributary length (2D) / area (3D) of the slave node on the slave surface
  // X_slave − Σ N_k X_k in the undeformed positions: a row along `dir` reads dir · (u_s − Σ N_k u_k) = −dir ·
  // separation, the current gap being normal · (separation + u_s − Σ N_k u_k)
  Eigen::Vector3d separation{0, 0, 0};
  std::array<Eigen::Vector3d, 2> tangent{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  // unit, ⊥ normal (2D: one)
};

/// Which master facets a slave node is projected on: every one (the exhaustive search), or only those whose bounding
/// box lies within search_distance of the node (a facet farther away cannot hold a projection within reach; its
/// projection, computed by the exhaustive search, can only keep a node out — see find_contact_points).
enum class FacetCandidates { All, Boxes };

/// Slave nodes whose projection falls on the master surface (facet edges included, within a relative 1e-6
/// of the facet size) at a distance ≤ search_distance, each with its closest such projection, in the positions of
/// the meshes given (separation: in those positions too). A node whose closest point is a facet's border counts when
/// no facet holds its projection inside — with `All`, any facet at any distance; with `Boxes`, a candidate facet.
std::vector<ContactPoint> find_contact_points(const Mesh& slave, const std::vector<Facet>& slave_surface,
                                              const Mesh& master, const std::vector<Facet>& master_surface,
                                              double search_distance,
                                              FacetCandidates candidates = FacetCandidates::Boxes);

/// The unit normal (and tangents) of a master facet at the point with shape function values N, in the meshes'
/// positions: how a contact point that keeps its master point sees the facet turn.
void facet_frame(const Mesh& master, const std::vector<int>& nodes, const std::vector<double>& N, ContactPoint& c);

}  // namespace rollsim
