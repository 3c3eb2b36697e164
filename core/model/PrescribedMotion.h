#pragma once
// The displacement a condition prescribes at a node and load factor: a translation scaled by the load factor,
// plus a rigid rotation whose angle grows with it (exact at any angle, not linearised).
#include <array>
#include <optional>

#include "model/Model.h"

namespace rollsim {

/// (R(λ θ) − I)(X − c): the displacement of the point X under the rotation at load factor λ (Rodrigues' formula).
std::array<double, 3> rotation_displacement(const RigidRotation& r, const std::array<double, 3>& X, double lf);

/// What `bc` prescribes for component `comp` of the node at X at load factor λ (nothing: the component is free).
std::optional<double> prescribed_value(const DisplacementBC& bc, const std::array<double, 3>& X, int comp, double lf);

}  // namespace rollsim
