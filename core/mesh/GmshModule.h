#pragma once
// The boundary between rollsim and its Gmsh module (rollsim_gmsh.so, built from GmshModule.cpp when Gmsh's library is
// found): the only code that links libgmsh, which maps OpenCASCADE and FLTK with it — dlopened by mesh/GmshLoader the
// first time a project imports a .msh file, so that no other run pays for loading them. The module reads a file
// through Gmsh's own API into GmshData, plain data in Gmsh's terms; mesh/GmshReader makes a body's mesh of it. Both
// sides are compiled from this header in one build: kGmshModuleAbi changes with the table.
#include <cstddef>
#include <string>
#include <vector>

namespace rollsim {

/// A .msh file's mesh as Gmsh's API gives it (gmsh::model::mesh::getNodes, getElements per entity, the physical
/// groups with their names and entities).
struct GmshData {
  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates;  // x, y, z of each node, in node_tags' order
  struct Block {                    // the elements of one type on one entity
    int dim = 0, entity = 0, type = 0;
    std::vector<std::size_t> element_tags, node_tags;  // node_tags: the elements' nodes, one element after another
  };
  std::vector<Block> blocks;
  struct Group {  // a physical group
    int dim = 0, tag = 0;
    std::string name;  // "" when the file names none
    std::vector<int> entities;
  };
  std::vector<Group> groups;
};

inline constexpr int kGmshModuleAbi = 1;
inline constexpr const char* kGmshModuleFile = "rollsim_gmsh.so";     // beside the executable
inline constexpr const char* kGmshModuleEnv = "ROLLSIM_GMSH_MODULE";  // overrides where it is
inline constexpr const char* kGmshModuleEntry = "rollsim_gmsh_module";

struct GmshModule {
  int abi = kGmshModuleAbi;
  /// Reads `file` into `out`; false with Gmsh's message in `error` when Gmsh cannot read it.
  bool (*read)(const std::string& file, GmshData& out, std::string& error);
};

}  // namespace rollsim
