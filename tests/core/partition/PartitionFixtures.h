#pragma once
// Shared helpers of the partition tests: the paper's samples as models, small blocks with chosen supports, and
// the Boolean-map algebra the tests check the extraction with.
#include <Eigen/Sparse>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/Decomposition.h"
#include "mesh/StructuredBlock.h"
#include "model/Model.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace rollsim::test {

inline Model sample_model(const std::string& name) {
  // a path, not string concatenation: GCC 12 warned of a false overflow in `std::string&& + const char*` here
  return build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / (name + ".json")));
}

/// Unit-element block nx × ny (× nz), E = 1000, nu = 0.3, no supports yet.
inline Model block_model(int dim, std::array<int, 3> n) {
  BlockSpec spec;
  spec.dim = dim;
  spec.n = n;
  spec.size = {double(n[0]), double(n[1]), double(n[2])};
  Model model;
  model.dim = dim;
  Body body;
  body.name = "block";
  body.mesh = make_block(spec);
  body.material.E = 1000.0;
  body.material.nu = 0.3;
  model.bodies.push_back(body);
  return model;
}

/// Nodes of body 0 inside the box [lo, hi] (inclusive, 1e-9 slack).
inline std::vector<int> nodes_in_box(const Model& m, std::array<double, 3> lo, std::array<double, 3> hi) {
  std::vector<int> ids;
  const Mesh& mesh = m.bodies[0].mesh;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    bool in = true;
    for (int a = 0; a < 3; ++a) in = in && mesh.nodes[n][a] >= lo[a] - 1e-9 && mesh.nodes[n][a] <= hi[a] + 1e-9;
    if (in) ids.push_back(n);
  }
  return ids;
}

/// Prescribes every component (value 0, or `value` on `comp` only when comp >= 0) on the nodes.
inline void support(Model& m, std::vector<int> nodes, int comp = -1, double value = 0.0) {
  DisplacementBC bc;
  bc.nodes = std::move(nodes);
  for (int c = 0; c < m.dim; ++c)
    if (comp < 0 || comp == c) bc.value[c] = value;
  m.displacements.push_back(bc);
}

/// L_s: body free dofs × local free dofs, 1 where local dof l is body dof free_dofs[l].
inline SparseMatrix local_to_body(const Subdomain& s, int body_free) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (size_t l = 0; l < s.free_dofs.size(); ++l) t.emplace_back(s.free_dofs[l], static_cast<int>(l), 1.0);
  SparseMatrix L(body_free, s.dofs->num_free());
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

inline std::vector<int> modes_per_group(const BodyDecomposition& dec) {
  std::vector<int> modes;
  for (const Group& g : dec.groups) modes.push_back(static_cast<int>(g.R.cols()));
  return modes;
}

}  // namespace rollsim::test
