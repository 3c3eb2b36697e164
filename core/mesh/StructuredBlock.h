#pragma once
// Structured rectangle (Q4) / box (H8) generator.
#include <array>

#include "mesh/Mesh.h"

namespace rollsim {

struct BlockSpec {
  int dim = 2;
  std::array<int, 3> n{1, 1, 1};              // elements along x, y, z
  std::array<double, 3> size{1.0, 1.0, 1.0};  // edge lengths
  std::array<double, 3> origin{0.0, 0.0, 0.0};
};

/// Nodes are numbered along the shortest direction first (the paper's cantilever numbering),
/// elements likewise. Surfaces and node sets: xmin, xmax, ymin, ymax (, zmin, zmax); element set "all".
Mesh make_block(const BlockSpec& spec);

}  // namespace rollsim
