#pragma once
// A block of unit elements, elastic (E 1000, ν 0.3) at finite strain, no supports: the body the kernel and cache
// tests assemble tangents of.
#include <array>

#include "mesh/StructuredBlock.h"
#include "model/Model.h"

namespace testing_support {

inline rollsim::Body finite_block(int dim, std::array<int, 3> n) {
  rollsim::BlockSpec spec;
  spec.dim = dim;
  spec.n = n;
  rollsim::Body body;
  body.mesh = rollsim::make_block(spec);
  body.material = {1000.0, 0.3};
  body.kinematics = rollsim::Kinematics::Finite;
  return body;
}

}  // namespace testing_support
