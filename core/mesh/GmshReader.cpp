#include "mesh/GmshReader.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <mutex>
#include <set>

#include "base/ModuleLoader.h"
#include "mesh/MeshImport.h"

namespace rollsim {

namespace {
constexpr int kLine2 = 1, kQuad4 = 3, kHex8 = 5;  // Gmsh element types

/// Gmsh's element types by name, for messages (gmsh.info's element type numbers).
std::string type_name(int type) {
  static const std::map<int, std::string> names{{2, "triangles"},
                                                {3, "quadrangles"},
                                                {5, "hexahedra"},
                                                {4, "tetrahedra"},
                                                {6, "prisms"},
                                                {7, "pyramids"},
                                                {8, "quadratic lines"},
                                                {9, "quadratic triangles"},
                                                {10, "9-node quadrangles"},
                                                {11, "quadratic tetrahedra"},
                                                {12, "27-node hexahedra"},
                                                {16, "8-node quadrangles"},
                                                {17, "20-node hexahedra"}};
  const auto it = names.find(type);
  return it != names.end() ? it->second : std::string("elements of Gmsh type ").append(std::to_string(type));
}

std::string group_name(const GmshData::Group& g) {
  return g.name.empty() ? std::string("physical_").append(std::to_string(g.tag)) : g.name;
}

/// The name as a deck holds set names: upper case (inp_body_mesh lower-cases them for the body).
std::string deck_name(const GmshData::Group& g) {
  std::string name = group_name(g);
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

/// The physical groups each (dim, entity) belongs to, for messages.
std::string groups_of(const GmshData& data, int dim, int entity) {
  std::string out;
  for (const GmshData::Group& g : data.groups)
    if (g.dim == dim && std::count(g.entities.begin(), g.entities.end(), entity))
      out.append(out.empty() ? " (physical group '" : "', '").append(group_name(g));
  return out.empty() ? out : out + "')";
}

void add_elements(const GmshData& data, int dim, const std::string& source, InpDeck& deck) {
  const int type = dim == 2 ? kQuad4 : kHex8, per = dim == 2 ? 4 : 8;
  for (const GmshData::Block& b : data.blocks) {
    if (b.dim > dim)
      throw MeshImportError(source + ": " + std::to_string(b.element_tags.size()) + " " + type_name(b.type) +
                            " of dimension " + std::to_string(b.dim) + " on Gmsh entity " + std::to_string(b.entity) +
                            ": a " + std::to_string(b.dim) + "D mesh in a " + std::to_string(dim) +
                            "D model (the project's dimension)");
    if (b.dim != dim) continue;
    if (b.type != type)
      throw MeshImportError(source + ": " + std::to_string(b.element_tags.size()) + " " + type_name(b.type) +
                            " on Gmsh entity " + std::to_string(b.entity) + groups_of(data, b.dim, b.entity) +
                            ": rollsim reads linear " + (dim == 2 ? "quadrangles in 2D" : "hexahedra in 3D") +
                            " (in Gmsh: Recombine, and Transfinite or Mesh.SubdivisionAlgorithm; ElementOrder 1)");
    for (size_t e = 0; e < b.element_tags.size(); ++e) {
      InpDeck::Element el{static_cast<int>(b.element_tags[e]), dim == 2 ? "CPE4" : "C3D8", {}};
      for (int k = 0; k < per; ++k) el.nodes.push_back(static_cast<int>(b.node_tags[e * per + k]));
      deck.elements.push_back(std::move(el));
    }
  }
}

/// The faces of the body's elements by their sorted node tags: (element tag, face 1…).
std::map<std::vector<int>, std::pair<int, int>> faces_of(const InpDeck& deck, int dim) {
  std::map<std::vector<int>, std::pair<int, int>> faces;
  const ElementType t = dim == 2 ? ElementType::Quad4 : ElementType::Hex8;
  for (const InpDeck::Element& e : deck.elements)
    for (int f = 0; f < (dim == 2 ? 4 : 6); ++f) {
      std::vector<int> nodes;
      for (const int local : facet_local_nodes(t, f)) nodes.push_back(e.nodes[static_cast<size_t>(local)]);
      std::sort(nodes.begin(), nodes.end());
      faces[nodes] = {e.id, f + 1};
    }
  return faces;
}

/// A group of one dimension less as a surface: each of its facets matched to an element's face.
void add_surface(const GmshData& data, const GmshData::Group& g, int dim, const std::string& source,
                 const std::map<std::vector<int>, std::pair<int, int>>& faces, InpDeck& deck) {
  const int facet = dim == 2 ? kLine2 : kQuad4, per = dim == 2 ? 2 : 4;
  auto& surface = deck.surfaces[deck_name(g)];
  for (const GmshData::Block& b : data.blocks) {
    if (b.dim != g.dim || !std::count(g.entities.begin(), g.entities.end(), b.entity)) continue;
    if (b.type != facet)
      throw MeshImportError(source + ": physical group '" + group_name(g) + "' holds " + type_name(b.type) +
                            ", which are no face of a linear " + (dim == 2 ? "quadrangle" : "hexahedron"));
    for (size_t e = 0; e < b.element_tags.size(); ++e) {
      std::vector<int> nodes(b.node_tags.begin() + static_cast<long>(e * per),
                             b.node_tags.begin() + static_cast<long>((e + 1) * per));
      std::sort(nodes.begin(), nodes.end());
      const auto it = faces.find(nodes);
      if (it == faces.end())
        throw MeshImportError(source + ": physical group '" + group_name(g) + "': its element " +
                              std::to_string(b.element_tags[e]) + " is no face of the body's elements");
      surface.push_back(it->second);
    }
  }
}

/// Every node of a group's entities (their elements' nodes).
std::vector<int> group_nodes(const GmshData& data, const GmshData::Group& g) {
  std::set<int> nodes;
  for (const GmshData::Block& b : data.blocks)
    if (b.dim == g.dim && std::count(g.entities.begin(), g.entities.end(), b.entity))
      for (const std::size_t n : b.node_tags) nodes.insert(static_cast<int>(n));
  return {nodes.begin(), nodes.end()};
}
}  // namespace

namespace {
/// The Gmsh module, loaded on the first call. Throws MeshImportError naming `file`, the module and why.
const GmshModule& gmsh_module(const std::filesystem::path& file) {
  static std::mutex mutex;
  static const GmshModule* module = nullptr;
  std::lock_guard lock(mutex);
  if (!module) {
    const std::filesystem::path path = module_path(kGmshModuleEnv, kGmshModuleFile);
    try {
      module = static_cast<const GmshModule*>(load_module(path, kGmshModuleEntry, false));
    } catch (const std::runtime_error& e) {
      throw MeshImportError(file.string() + ": .msh files are read by Gmsh's library, through the module " +
                            path.string() + ", which cannot be loaded: " + e.what() +
                            " (it is built beside rollsim when Debian's libgmsh-dev is installed; or write the "
                            "mesh as a CalculiX / Abaqus .inp deck)");
    }
    if (module->abi != kGmshModuleAbi) {
      module = nullptr;
      throw MeshImportError(file.string() + ": the Gmsh module " + path.string() +
                            " was built by another rollsim: rebuild both together");
    }
  }
  return *module;
}
}  // namespace

GmshData read_gmsh_file(const std::filesystem::path& file) {
  const GmshModule& module = gmsh_module(file);
  GmshData data;
  std::string error;
  if (!module.read(file.string(), data, error)) throw MeshImportError(file.string() + ": Gmsh: " + error);
  return data;
}

InpDeck gmsh_deck(const GmshData& data, int dim, const std::string& source) {
  InpDeck deck;
  for (size_t n = 0; n < data.node_tags.size(); ++n)
    deck.nodes[static_cast<int>(data.node_tags[n])] = {data.coordinates[3 * n], data.coordinates[3 * n + 1],
                                                       data.coordinates[3 * n + 2]};
  add_elements(data, dim, source, deck);
  const auto faces = faces_of(deck, dim);
  for (const GmshData::Group& g : data.groups) {
    if (g.dim == dim) {
      auto& set = deck.element_sets[deck_name(g)];
      for (const GmshData::Block& b : data.blocks)
        if (b.dim == dim && std::count(g.entities.begin(), g.entities.end(), b.entity))
          for (const std::size_t e : b.element_tags) set.push_back(static_cast<int>(e));
    }
    if (g.dim == dim - 1) add_surface(data, g, dim, source, faces, deck);
    deck.node_sets[deck_name(g)] = group_nodes(data, g);
  }
  return deck;
}

Mesh read_msh(const std::filesystem::path& file, int dim, const std::string& element_set) {
  return inp_body_mesh(gmsh_deck(read_gmsh_file(file), dim, file.string()), dim, element_set, file.string());
}

}  // namespace rollsim
