#pragma once
// A mesh from a CalculiX / Abaqus input deck (.inp): the keywords that describe a mesh — *NODE, *ELEMENT, *NSET,
// *ELSET (both with GENERATE), *SURFACE (TYPE=ELEMENT: an element or element set with its face S1…S6) and
// *INCLUDE — read into one body's Mesh; every other keyword (materials, steps, loads) is listed, not read. Keywords
// and set names are case-insensitive (CalculiX upper-cases them; so does this reader). Linear quadrilaterals (CPE4,
// CPS4, CAX4 and their R/H/I variants) and hexahedra (C3D8, C3D8R, C3D8I, C3D8H) are read: their node orders are
// rollsim's Q4 and H8 orders and face Sk is the facet local k − 1 (io/CalculixWriter writes the same). Triangles,
// tetrahedra, wedges and quadratic elements are refused with the line that holds them.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "mesh/Mesh.h"
#include "mesh/MeshImport.h"

namespace rollsim {

/// What a deck holds, in its own numbering.
struct InpDeck {
  struct Element {
    int id = 0;
    std::string type;  // upper case, e.g. C3D8R
    std::vector<int> nodes;
  };
  std::map<int, std::array<double, 3>> nodes;
  std::vector<Element> elements;  // in the file's order
  std::map<std::string, std::vector<int>> node_sets, element_sets;
  std::map<std::string, std::vector<std::pair<int, int>>> surfaces;  // (element id, face 1…6)
  std::vector<std::string> ignored;                                  // keywords not read, once each, in order
};

/// Reads `file` (and what it *INCLUDEs, relative to it). Throws MeshImportError (the file, the line and what is wrong
/// there).
InpDeck read_inp_deck(const std::filesystem::path& file);
/// The same from text already in memory (`source` names it in messages; *INCLUDE is relative to its folder).
InpDeck parse_inp_deck(const std::string& text, const std::string& source);

/// The body of `deck` made of the elements of `element_set` (every element when empty), its nodes numbered
/// compactly in the order of their ids; the node sets, element sets and surfaces restricted to it (those with
/// nothing in it dropped), their names in lower case. `dim` 2: quadrilaterals (z must be 0); 3: hexahedra.
/// Throws MeshImportError (an unknown element set — at field element_set —, a mixed or unsupported element type, a
/// missing node).
Mesh inp_body_mesh(const InpDeck& deck, int dim, const std::string& element_set, const std::string& source);

}  // namespace rollsim
