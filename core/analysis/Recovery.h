#pragma once
// Post-processing of one body from its full displacement vector: element and nodal stresses,
// and nodal forces (internal minus external), whose values at supported dofs are the reactions.
#include "analysis/Results.h"
#include "model/Model.h"

namespace rollsim {

/// `load_factor` scales the external loads the nodal forces are taken against (a load increment's i / N). `state`:
/// the committed integration-point state of the body's elements (element-major) for a material with state — the
/// stresses come from it, and the element mean of the equivalent plastic strain fills plastic_strain.
BodyResults recover(const Model& model, int body_index, Eigen::VectorXd displacement, double load_factor = 1.0,
                    const std::vector<double>& state = {});

/// A conducting body's nodal temperatures into its results, with each element's mean of them as its temperature.
void set_nodal_temperature(const Mesh& mesh, const Eigen::VectorXd& T, BodyResults& r);

/// Sum of nodal forces over a node set, per component.
std::array<double, 3> set_resultant(const BodyResults& r, int dim, const std::vector<int>& nodes);

}  // namespace rollsim
