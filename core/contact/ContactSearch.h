#pragma once
// Contact search in the undeformed configuration: each slave node is projected on the master surface
// (node-to-segment in 2D, node-to-face on bilinear faces in 3D); the projection gives the master nodes,
// their interpolation weights, the master's outward normal and the initial gap.
#include <Eigen/Dense>
#include <vector>

#include "mesh/Mesh.h"

namespace rollsim {

struct ContactPoint {
  int slave_node = 0;
  std::vector<int> master_nodes;    // nodes of the master facet holding the projection
  std::vector<double> N;            // their shape function values at the projection (sum 1)
  Eigen::Vector3d normal{0, 0, 0};  // master outward unit normal at the projection (points towards the slave)
  double gap = 0;                   // normal · (x_slave − x_projection): > 0 open, < 0 penetrating [length]
  double weight = 0;                // tributary length (2D) / area (3D) of the slave node on the slave surface
};

/// Slave nodes whose projection falls on the master surface (facet edges included, within a relative 1e-6
/// of the facet size) at a distance ≤ search_distance, each with its closest such projection.
std::vector<ContactPoint> find_contact_points(const Mesh& slave, const std::vector<Facet>& slave_surface,
                                              const Mesh& master, const std::vector<Facet>& master_surface,
                                              double search_distance);

}  // namespace rollsim
