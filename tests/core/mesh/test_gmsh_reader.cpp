// A Gmsh file read into a body's mesh through Gmsh's own library: Cook's membrane (MSH 4.1 ASCII) has the nodes of
// the .inp deck the generator script writes, its physical groups as an element set, a node set and a surface on the
// elements' faces; a binary 3D block reads its hexahedra and faces; triangles, a 3D mesh in a 2D model and a file Gmsh
// cannot parse are refused with the file and what is wrong (a missing module: tests/app/test_mesh_import.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../../common/FreshDir.h"
#include "mesh/ElementQuality.h"
#include "mesh/GmshReader.h"
#include "mesh/InpReader.h"

namespace test_gmsh_reader {

using namespace rollsim;

#ifdef ROLLSIM_HAVE_GMSH
namespace {
const std::filesystem::path kSource = ROLLSIM_SOURCE_DIR;

std::string refusal(const std::filesystem::path& file, int dim) {
  try {
    read_msh(file, dim, "");
  } catch (const MeshImportError& e) {
    return e.what();
  }
  return "accepted";
}
}  // namespace

TEST(GmshReader, CooksMembraneHasTheDecksNodesAndItsGroupsAsSets) {
  const Mesh msh = read_msh(kSource / "samples/cooks-membrane-gmsh-2d.msh", 2, "panel");
  const Mesh inp = inp_body_mesh(read_inp_deck(kSource / "samples/cooks-membrane-2d.inp"), 2, "", "inp");
  ASSERT_EQ(msh.num_elements(), 256);
  ASSERT_EQ(msh.num_nodes(), inp.num_nodes());
  // the same points (in another order): every node of one is a node of the other
  for (const auto& x : msh.nodes) {
    double nearest = 1e300;
    for (const auto& y : inp.nodes) nearest = std::min(nearest, std::hypot(x[0] - y[0], x[1] - y[1]));
    EXPECT_LT(nearest, 1e-9);
  }
  EXPECT_EQ(msh.element_sets.at("panel").size(), 256u);
  EXPECT_EQ(msh.node_sets.at("left").size(), 17u);
  ASSERT_EQ(msh.surfaces.at("right").size(), 16u);
  for (const Facet& f : msh.surfaces.at("right"))
    for (const int local : facet_local_nodes(msh.type, f.local))
      EXPECT_NEAR(msh.nodes[static_cast<size_t>(msh.element(f.element)[local])][0], 48.0, 1e-9);
  EXPECT_NO_THROW(check_element_orientation(msh));
}

TEST(GmshReader, ABinaryHexahedralBlockReadsItsFaces) {
  const Mesh m = read_msh(kSource / "tests/data/meshes/block-3d.msh", 3, "block");
  EXPECT_EQ(m.num_elements(), 16);
  EXPECT_EQ(m.num_nodes(), 5 * 3 * 3);
  EXPECT_EQ(m.surfaces.at("fixed").size(), 4u);
  EXPECT_EQ(m.surfaces.at("loaded").size(), 4u);
  EXPECT_EQ(m.node_sets.at("fixed").size(), 9u);
  for (const int n : m.node_sets.at("loaded")) EXPECT_NEAR(m.nodes[static_cast<size_t>(n)][0], 2.0, 1e-12);
  EXPECT_NO_THROW(check_element_orientation(m));
}

TEST(GmshReader, WhatItCannotReadIsRefusedNamingTheFileAndWhy) {
  const std::string triangles = refusal(kSource / "tests/data/meshes/triangles-2d.msh", 2);
  EXPECT_NE(triangles.find("triangles on Gmsh entity 1 (physical group 'square'): rollsim reads linear quadrangles"),
            std::string::npos)
      << triangles;
  const std::string wrong_dim = refusal(kSource / "tests/data/meshes/block-3d.msh", 2);
  EXPECT_NE(wrong_dim.find("block-3d.msh: 16 hexahedra of dimension 3 on Gmsh entity 1: a 3D mesh in a 2D model"),
            std::string::npos)
      << wrong_dim;
  const std::filesystem::path dir = fresh_dir("gmsh-reader");
  std::ofstream(dir / "v9.msh") << "$MeshFormat\n9.1 0 8\n$EndMeshFormat\n";
  const std::string version = refusal(dir / "v9.msh", 2);
  EXPECT_NE(version.find("v9.msh: Gmsh: "), std::string::npos) << version;
  // a file Gmsh could not read leaves it able to read the next (Gmsh 4.8 read every later file as empty)
  EXPECT_EQ(refusal(kSource / "tests/data/meshes/block-3d.msh", 3), "accepted");
}
#endif

}  // namespace test_gmsh_reader
