#pragma once
// Warnings for models whose answer double precision cannot be trusted to carry, said before the run and kept in
// summary.json (`warnings`): bodies whose Young's moduli span many decades (a stiffness ratio of 1e15 left reactions
// of garbage reported `converged`), and nearly incompressible bodies under full integration, which lock (at
// ν = 0.4999999 about 1000× too stiff).
#include <string>
#include <vector>

#include "model/Model.h"

namespace rollsim {

/// Ratios of the largest to the smallest Young's modulus from which a warning is given: half the 16 digits lost.
inline constexpr double kStiffnessRatioWarning = 1e8;
/// Poisson's ratio above which a fully integrated body is said to lock.
inline constexpr double kLockingPoisson = 0.49;

std::vector<std::string> conditioning_warnings(const Model& model);

}  // namespace rollsim
