// The Gmsh module (mesh/GmshModule.h): Gmsh's API reads the file — MSH 4 and 2, ASCII and binary — and the mesh is
// copied out as GmshData. Gmsh keeps one global model, so reads are serialised, and the model is cleared after each.
#include "mesh/GmshModule.h"

#include <gmsh.h>

#include <mutex>

namespace rollsim {

namespace {
std::mutex gmsh_mutex;

void copy_model(GmshData& out) {
  std::vector<double> parametric;
  gmsh::model::mesh::getNodes(out.node_tags, out.coordinates, parametric, -1, -1, false, false);
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities);
  for (const auto& [dim, tag] : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> elements, nodes;
    gmsh::model::mesh::getElements(types, elements, nodes, dim, tag);
    for (std::size_t i = 0; i < types.size(); ++i)
      out.blocks.push_back({dim, tag, types[i], std::move(elements[i]), std::move(nodes[i])});
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups) {
    GmshData::Group g{dim, tag, {}, {}};
    gmsh::model::getPhysicalName(dim, tag, g.name);
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, g.entities);
    out.groups.push_back(std::move(g));
  }
}

bool initialized = false;

void start() {
  if (initialized) return;
  gmsh::initialize(0, nullptr, false);  // no configuration files of the user's: the same reading everywhere
  gmsh::option::setNumber("General.Terminal", 0);
  initialized = true;
}

bool read(const std::string& file, GmshData& out, std::string& error) {
  std::lock_guard lock(gmsh_mutex);
  try {
    start();
    gmsh::clear();
    gmsh::open(file);
    copy_model(out);
    gmsh::clear();
    return true;
  } catch (const std::string& message) {  // Gmsh 4.8's API throws its last error as a string
    error = message;
  } catch (const std::exception& e) {
    error = e.what();
  }
  // after an error Gmsh 4.8 reads every later file as empty: start it afresh for the next one
  gmsh::finalize();
  initialized = false;
  return false;
}

const GmshModule kModule{kGmshModuleAbi, read};
}  // namespace

}  // namespace rollsim

extern "C" __attribute__((visibility("default"))) const rollsim::GmshModule* rollsim_gmsh_module() {
  return &rollsim::kModule;
}
