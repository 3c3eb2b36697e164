#pragma once
// The tributary measure of every node of a surface, computed here independently of the contact search: half of each
// adjacent edge's length (2D), a quarter of each adjacent face's area (3D; exact for the parallelogram faces of the
// block samples).
#include <Eigen/Dense>
#include <map>
#include <vector>

#include "mesh/Mesh.h"

namespace testing_support {

inline std::map<int, double> tributary_measure(const rollsim::Mesh& mesh, const std::vector<rollsim::Facet>& surface) {
  std::map<int, double> measure;
  auto point = [&](int n) { return Eigen::Vector3d(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]); };
  for (const rollsim::Facet& f : surface) {
    std::vector<int> nodes;
    for (const int local : rollsim::facet_local_nodes(mesh.type, f.local))
      nodes.push_back(mesh.element(f.element)[local]);
    const double size = nodes.size() == 2
                            ? (point(nodes[1]) - point(nodes[0])).norm()
                            : 0.5 * (point(nodes[2]) - point(nodes[0])).cross(point(nodes[3]) - point(nodes[1])).norm();
    for (const int n : nodes) measure[n] += size / static_cast<double>(nodes.size());
  }
  return measure;
}

}  // namespace testing_support
