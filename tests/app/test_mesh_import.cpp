// A mesh imported from a CalculiX deck (`mesh.type: import`): the deck `rollsim export-ccx` writes of a two-body
// model, read back body by body through its element sets, gives the same model and the same results as the
// generated meshes it came from; its path is relative to the project file; a deck the importer cannot read is
// invalid input at the mesh's `file` (exit 2), for `check` as for `run`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_mesh_import {

using json = nlohmann::json;

namespace {
const std::string kSample = ROLLSIM_SOURCE_DIR "/samples/block-indent-3d-10x6x4.json";

/// The sample with both meshes read from `deck` (each body its element set E_<NAME>) and the deck's set names.
json imported(const std::string& deck) {
  json p = json::parse(read_text(kSample));
  p["bodies"][0]["mesh"] = {{"type", "import"}, {"file", deck}, {"element_set", "E_BASE"}};
  p["bodies"][1]["mesh"] = {{"type", "import"}, {"file", deck}, {"element_set", "e_block"}};  // any case
  p["boundary_conditions"][0]["set"] = "n_base_zmin";
  p["boundary_conditions"][1]["set"] = "n_block_zmax";
  p["contacts"][0]["slave_surface"] = "s_base_zmax";
  p["contacts"][0]["master_surface"] = "s_block_zmin";
  return p;
}
}  // namespace

TEST(MeshImport, AnExportedDeckReadBackGivesTheSameResults) {
  const std::string dir = make_temp_dir("mesh-import");
  ASSERT_EQ(run_rollsim({"export-ccx", kSample, dir + "/deck.inp"}).exit_code, 0);
  write_text(dir + "/p.json", imported("deck.inp").dump(1));  // relative to the project file, not to the cwd
  const RunResult a = run_rollsim({"run", kSample, "--out", dir + "/generated", "--quiet"});
  const RunResult b = run_rollsim({"run", dir + "/p.json", "--out", dir + "/imported", "--quiet"});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const json sa = json::parse(read_text(dir + "/generated/summary.json"));
  const json sb = json::parse(read_text(dir + "/imported/summary.json"));
  EXPECT_EQ(sa["model"]["nodes"], sb["model"]["nodes"]);
  EXPECT_EQ(sa["model"]["elements"], sb["model"]["elements"]);
  const json& ca = sa["results"]["contact"]["block-base"];
  const json& cb = sb["results"]["contact"]["block-base"];
  EXPECT_EQ(ca["active_nodes"], cb["active_nodes"]);
  EXPECT_NEAR(ca["normal_force"].get<double>(), cb["normal_force"].get<double>(),
              1e-12 * std::abs(ca["normal_force"].get<double>()));
  const json& pa = sa["results"]["probes"]["base-centre"]["displacement"];
  const json& pb = sb["results"]["probes"]["base-centre"]["displacement"];
  for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(pa[k].get<double>(), pb[k].get<double>(), 1e-15);
}

TEST(MeshImport, AnUnreadableDeckIsInvalidInputAtTheMeshFile) {
  const std::string dir = make_temp_dir("mesh-import-bad");
  write_text(dir + "/tets.inp",
             "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n*ELEMENT, TYPE=C3D4, ELSET=E_BASE\n"
             "1, 1,2,3,4\n");
  write_text(dir + "/p.json", imported("tets.inp").dump(1));
  write_text(dir + "/q.json", imported("nowhere.inp").dump(1));
  for (const std::vector<std::string>& command : {std::vector<std::string>{"check", dir + "/p.json"},
                                                  {"run", dir + "/p.json", "--out", dir + "/out", "--quiet"}}) {
    const RunResult r = run_rollsim(command);
    EXPECT_EQ(r.exit_code, 2) << command[0] << "\n" << r.err;
    EXPECT_NE(r.err.find("bodies[0].mesh.file: " + dir + "/tets.inp: element 1 is a C3D4: tetrahedra are not"),
              std::string::npos)
        << r.err;
  }
  const RunResult r = run_rollsim({"check", dir + "/q.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bodies[0].mesh.file: " + dir + "/nowhere.inp: cannot be read"), std::string::npos) << r.err;
  // a set the deck does not hold is the element_set's fault, with the deck's sets listed
  json p = imported("tets.inp");
  p["bodies"][0]["mesh"]["element_set"] = "E_SLAB";
  write_text(dir + "/s.json", p.dump(1));
  const RunResult s = run_rollsim({"check", dir + "/s.json"});
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("bodies[0].mesh.element_set: " + dir +
                       "/tets.inp: no element set named 'E_SLAB' (the deck "
                       "has: E_BASE)"),
            std::string::npos)
      << s.err;
}

}  // namespace test_mesh_import

#ifdef ROLLSIM_HAVE_GMSH
namespace test_mesh_import {

namespace {
json summary_of(const std::string& project, const std::string& out) {
  const RunResult r = run_rollsim({"run", project, "--out", out, "--quiet"});
  EXPECT_EQ(r.exit_code, 0) << project << "\n" << r.err;
  return json::parse(read_text(out + "/summary.json"));
}
}  // namespace

TEST(MeshImport, CooksMembraneFromGmshGivesTheDecksAnswer) {
  // the same 16 × 16 panel meshed by Gmsh (.msh, physical groups panel / left / right) and by the script's .inp deck
  const std::string dir = make_temp_dir("mesh-import-gmsh");
  const json a = summary_of(ROLLSIM_SOURCE_DIR "/samples/cooks-membrane-gmsh-2d.json", dir + "/msh");
  const json b = summary_of(ROLLSIM_SOURCE_DIR "/samples/cooks-membrane-2d.json", dir + "/inp");
  const double tip_a = a["results"]["probes"]["tip"]["displacement"][1],
               tip_b = b["results"]["probes"]["tip"]["displacement"][1];
  EXPECT_NEAR(tip_a, tip_b, 1e-9 * std::abs(tip_b));
  EXPECT_NEAR(tip_a, 7.59, 0.01);  // docs/VALIDATION.md: B-bar on 16 × 16
}

TEST(MeshImport, AGmshBlockGivesTheGeneratedBlocksAnswer) {
  // a 2 × 1 × 1 cantilever of 4 × 2 × 2 hexahedra: generated, and read from Gmsh's binary file of the same mesh
  const std::string dir = make_temp_dir("mesh-import-gmsh-3d");
  json p = {{"name", "block"},
            {"dimension", 3},
            {"materials", {{{"name", "steel"}, {"E", 210000.0}, {"nu", 0.3}}}},
            {"bodies",
             {{{"name", "b"},
               {"material", "steel"},
               {"mesh", {{"type", "block"}, {"nx", 4}, {"ny", 2}, {"nz", 2}, {"lx", 2.0}, {"ly", 1.0}, {"lz", 1.0}}}}}},
            {"boundary_conditions",
             {{{"type", "displacement"}, {"body", "b"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}, {"uz", 0.0}},
              {{"type", "traction"}, {"body", "b"}, {"surface", "xmax"}, {"tz", -10.0}}}},
            {"probes", {{{"name", "tip"}, {"at", {2.0, 1.0, 1.0}}}}}};
  write_text(dir + "/generated.json", p.dump(1));
  p["bodies"][0]["mesh"] = {
      {"type", "import"}, {"file", ROLLSIM_SOURCE_DIR "/tests/data/meshes/block-3d.msh"}, {"element_set", "block"}};
  p["boundary_conditions"][0]["set"] = "fixed";
  p["boundary_conditions"][1]["surface"] = "loaded";
  write_text(dir + "/imported.json", p.dump(1));
  const json a = summary_of(dir + "/generated.json", dir + "/a"), b = summary_of(dir + "/imported.json", dir + "/b");
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(a["results"]["probes"]["tip"]["displacement"][c].get<double>(),
                b["results"]["probes"]["tip"]["displacement"][c].get<double>(), 1e-12)
        << c;
  EXPECT_LT(a["results"]["probes"]["tip"]["displacement"][2].get<double>(), -1e-5);  // it bends down
}

TEST(MeshImport, AGmshMeshOfTrianglesIsInvalidInputAtTheMeshFile) {
  const std::string dir = make_temp_dir("mesh-import-gmsh-bad");
  const json p = {
      {"dimension", 2},
      {"materials", {{{"name", "m"}, {"E", 1.0}, {"nu", 0.3}}}},
      {"bodies",
       {{{"name", "b"},
         {"material", "m"},
         {"mesh", {{"type", "import"}, {"file", ROLLSIM_SOURCE_DIR "/tests/data/meshes/triangles-2d.msh"}}}}}}};
  write_text(dir + "/p.json", p.dump(1));
  const RunResult r = run_rollsim({"check", dir + "/p.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bodies[0].mesh.file: " ROLLSIM_SOURCE_DIR "/tests/data/meshes/triangles-2d.msh: 14 triangles"),
            std::string::npos)
      << r.err;
}

TEST(MeshImport, AMissingGmshModuleIsInvalidInputNamingItAndTheWayOut) {
  setenv("ROLLSIM_GMSH_MODULE", "/nonexistent/rollsim_gmsh.so", 1);  // the child inherits it
  const RunResult r = run_rollsim({"check", ROLLSIM_SOURCE_DIR "/samples/cooks-membrane-gmsh-2d.json"});
  unsetenv("ROLLSIM_GMSH_MODULE");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("through the module /nonexistent/rollsim_gmsh.so, which cannot be loaded"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("libgmsh-dev"), std::string::npos) << r.err;
}

}  // namespace test_mesh_import
#endif
