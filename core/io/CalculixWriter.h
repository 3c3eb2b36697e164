#pragma once
// CalculiX (.inp) input for the same model — same mesh, elements (CPE4 / C3D8), materials,
// supports and nodal forces — so results and run time can be compared with a peer FE code.
#include <string>

#include "model/Model.h"

namespace rollsim {

/// Throws std::invalid_argument for what has no translation yet (pressure loads).
std::string calculix_input(const Model& model);

}  // namespace rollsim
