#pragma once
// A body's mesh from a Gmsh file (.msh, version 4 or 2, ASCII or binary), read by Gmsh's own library (the module of
// mesh/GmshModule.h, loaded on first use). Physical groups become named sets: a group of the model's dimension an
// element set (and the mesh spec's element_set picks one), a group of one dimension less a surface — its lines (2D) or
// quadrangles (3D) matched to the faces of the body's elements — and every group a node set. Unnamed groups are called
// by their tag ("physical_3"); names are lower-cased, as for .inp decks. Linear quadrangles (2D) and hexahedra (3D)
// are read, with their Gmsh node orders (the same as rollsim's Q4 and H8); triangles, tetrahedra, prisms, pyramids and
// higher orders are refused with their count and the group they are in.
#include <filesystem>
#include <string>

#include "mesh/GmshModule.h"
#include "mesh/InpReader.h"
#include "mesh/Mesh.h"

namespace rollsim {

/// The file through the Gmsh module. Throws MeshImportError (the module missing, or Gmsh's own message).
GmshData read_gmsh_file(const std::filesystem::path& file);

/// `data` as a deck inp_body_mesh builds bodies from, for a `dim`-dimensional model (its quadrangles as CPE4, its
/// hexahedra as C3D8: the same node orders). Throws MeshImportError naming `source`.
InpDeck gmsh_deck(const GmshData& data, int dim, const std::string& source);

/// The body made of `element_set`'s elements (every element of the model's dimension when empty).
Mesh read_msh(const std::filesystem::path& file, int dim, const std::string& element_set);

}  // namespace rollsim
