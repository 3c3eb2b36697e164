#pragma once
// Mesh generators as seen from the project file: parameter checks that need more than one
// field, size estimates (before allocating), the set names each generator provides, and generation; a mesh
// imported from a file (`type: import`, mesh/MeshImport) is one more kind, its checks the file's reading.
#include <set>
#include <string>
#include <vector>

#include "base/Schema.h"
#include "mesh/Mesh.h"
#include "mesh/StructuredBlock.h"

namespace rollsim {

void check_mesh_spec(const json& mesh, const std::string& path, int dim, std::vector<Issue>& issues);
double estimated_elements(const json& mesh, int dim);
/// Names of the surfaces (and node sets of the same name) the generator creates; an imported mesh's surfaces.
std::set<std::string> generator_set_names(const json& mesh, int dim);
/// Names of the node sets the mesh has: the generator's (its surfaces'); an imported mesh's node sets, its surfaces'
/// and `all`.
std::set<std::string> generator_node_set_names(const json& mesh, int dim);
Mesh make_mesh(const json& mesh, int dim);

}  // namespace rollsim
