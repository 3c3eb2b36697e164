#pragma once
// CalculiX (.inp) input for the same model — same mesh, elements (CPE4 / C3D8), materials,
// supports, nodal forces, pressures and 3D contact pairs — so results and run time can be compared with a peer FE code.
#include <string>

#include "model/Model.h"

namespace rollsim {

/// Name CalculiX gives (upper case, as printed in its .dat file) to the node set of `set` on `body`.
std::string calculix_set_name(const Model& model, int body, const std::string& set);

/// The whole .inp: node ids are our node index + 1 (bodies numbered one after the other), element ids likewise.
/// Contact pairs: tied -> *TIE, frictionless -> node-to-surface *CONTACT PAIR with a stiff linear penalty (3D).
/// Throws std::invalid_argument for what has no CalculiX equivalent (the B-bar formulation; contact in 2D).
std::string calculix_input(const Model& model);

}  // namespace rollsim
