// CalculiX export: the .inp structure of a 2×1 block, element orientation, and (when `ccx` is on PATH) the same
// total reactions as our analysis on small 2D and 3D cantilevers, with prescribed tips, forces, pressures, body
// forces and tractions; 3D contact written as *TIE / *CONTACT PAIR on element-face surfaces and giving CalculiX the
// same contact force (tied: to 1e-5; frictionless: within the penalty's 3 %), 2D contact refused (it exported
// unconnected bodies before).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "analysis/LinearStatic.h"
#include "fem/Loads.h"
#include "io/CalculixWriter.h"
#include "io/Summary.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_calculix_writer {

using namespace rollsim;
namespace fs = std::filesystem;

namespace {

/// A unit-element cantilever nx × ny (× nz), clamped at xmin, with the given extra boundary conditions.
Model cantilever(int dim, std::array<int, 3> n, const std::string& extra_bcs, const std::string& formulation = "full") {
  std::ostringstream s;
  s << R"({"name": "t", "dimension": )" << dim << R"(, "materials": [{"name": "m", "E": 1000, "nu": 0.3}],)"
    << R"( "bodies": [{"name": "beam", "material": "m", "formulation": ")" << formulation << R"(", "mesh": )"
    << R"({"type": "block", "nx": )" << n[0] << ", \"ny\": " << n[1] << ", \"lx\": " << n[0] << ", \"ly\": " << n[1];
  if (dim == 3) s << ", \"nz\": " << n[2] << ", \"lz\": " << n[2];
  s << R"(}, "node_sets": [{"name": "tip", "box_min": )";
  if (dim == 2)
    s << "[" << n[0] << ", " << n[1] << "], \"box_max\": [" << n[0] << ", " << n[1] << "]";
  else
    s << "[" << n[0] << ", 0, " << n[2] << "], \"box_max\": [" << n[0] << ", " << n[1] << ", " << n[2] << "]";
  s << R"(}]}], "boundary_conditions": [{"type": "displacement", "body": "beam", "set": "xmin", "ux": 0, "uy": 0)"
    << (dim == 3 ? ", \"uz\": 0}" : "}") << extra_bcs << "]}";
  return build_model(parse_project(s.str(), "test"));
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

/// Lines after the keyword line `key` up to the next keyword.
std::vector<std::string> block_after(const std::vector<std::string>& lines, const std::string& key) {
  std::vector<std::string> out;
  auto it = std::find(lines.begin(), lines.end(), key);
  if (it == lines.end()) return out;
  for (++it; it != lines.end() && (*it).rfind("*", 0) != 0; ++it) out.push_back(*it);
  return out;
}

std::vector<double> numbers(const std::string& line) {
  std::vector<double> v;
  std::istringstream in(line);
  for (std::string tok; std::getline(in, tok, ',');) v.push_back(std::stod(tok));
  return v;
}

/// Element ids -> node ids and node id -> coordinates, read back from the .inp.
struct Parsed {
  std::map<int, std::array<double, 3>> x;
  std::vector<std::vector<int>> elements;
};

Parsed parse(const std::vector<std::string>& lines, const std::string& element_key) {
  Parsed p;
  for (const auto& l : block_after(lines, "*NODE, NSET=NALL")) {
    const auto v = numbers(l);
    p.x[static_cast<int>(v[0])] = {v[1], v[2], v[3]};
  }
  for (const auto& l : block_after(lines, element_key)) {
    std::vector<int> conn;
    for (double d : numbers(l)) conn.push_back(static_cast<int>(d));
    p.elements.push_back({conn.begin() + 1, conn.end()});
  }
  return p;
}

double cross_z(const std::array<double, 3>& o, const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

}  // namespace

TEST(CalculixWriter, TwoByOneBlock2D) {
  const Model m = cantilever(2, {2, 1, 1}, R"(, {"type": "force", "body": "beam", "set": "xmax", "fy": -1.5})");
  const auto lines = lines_of(calculix_input(m));
  const Parsed p = parse(lines, "*ELEMENT, TYPE=CPE4, ELSET=E_BEAM");
  ASSERT_EQ(p.x.size(), 6u);
  ASSERT_EQ(p.elements.size(), 2u);
  for (const auto& e : p.elements) {
    ASSERT_EQ(e.size(), 4u);
    for (int a = 0; a < 4; ++a)  // counter-clockwise at every corner, as CPE4 wants
      EXPECT_GT(cross_z(p.x.at(e[a]), p.x.at(e[(a + 1) % 4]), p.x.at(e[(a + 3) % 4])), 0.0);
  }
  const auto xmin = block_after(lines, "*NSET, NSET=N_BEAM_XMIN");
  ASSERT_EQ(xmin.size(), 1u);
  for (double id : numbers(xmin[0])) EXPECT_EQ(p.x.at(static_cast<int>(id))[0], 0.0);
  EXPECT_EQ(numbers(xmin[0]).size(), 2u);
  EXPECT_EQ(block_after(lines, "*ELASTIC"), std::vector<std::string>{"1000, 0.29999999999999999"});
  EXPECT_EQ(block_after(lines, "*SOLID SECTION, ELSET=E_BEAM, MATERIAL=M_BEAM"), std::vector<std::string>{"1."});
  const std::vector<std::string> fixed{"N_BEAM_XMIN, 1, 1, 0", "N_BEAM_XMIN, 2, 2, 0"};
  EXPECT_EQ(block_after(lines, "*BOUNDARY"), fixed);
  EXPECT_EQ(block_after(lines, "*CLOAD"), std::vector<std::string>{"N_BEAM_XMAX, 2, -1.5"});
  EXPECT_EQ(block_after(lines, "*NODE PRINT, NSET=N_BEAM_XMIN, TOTALS=ONLY"), std::vector<std::string>{"RF"});
  EXPECT_NE(std::find(lines.begin(), lines.end(), "*STEP"), lines.end());
  EXPECT_NE(std::find(lines.begin(), lines.end(), "*STATIC"), lines.end());
  EXPECT_EQ(lines.back(), "*END STEP");
}

TEST(CalculixWriter, BrickOrientation3D) {
  const Model m = cantilever(3, {2, 1, 1}, R"(, {"type": "pressure", "body": "beam", "surface": "zmax", "value": 2})");
  const auto lines = lines_of(calculix_input(m));
  const Parsed p = parse(lines, "*ELEMENT, TYPE=C3D8, ELSET=E_BEAM");
  ASSERT_EQ(p.x.size(), 12u);
  ASSERT_EQ(p.elements.size(), 2u);
  for (const auto& e : p.elements) {
    ASSERT_EQ(e.size(), 8u);
    for (int a = 0; a < 4; ++a) {  // bottom 1-2-3-4 counter-clockwise from +z, top 5-8 right above
      EXPECT_GT(cross_z(p.x.at(e[a]), p.x.at(e[(a + 1) % 4]), p.x.at(e[(a + 3) % 4])), 0.0);
      const auto &lo = p.x.at(e[a]), &hi = p.x.at(e[a + 4]);
      EXPECT_EQ(lo[0], hi[0]);
      EXPECT_EQ(lo[1], hi[1]);
      EXPECT_GT(hi[2], lo[2]);
    }
  }
  EXPECT_EQ(block_after(lines, "*DLOAD"), (std::vector<std::string>{"1, P2, 2", "2, P2, 2"}));  // top = S2
}

TEST(CalculixWriter, RefusesBBar) {
  EXPECT_THROW(calculix_input(cantilever(2, {2, 1, 1}, "", "bbar")), std::invalid_argument);
}

namespace {

/// CalculiX's "total force (fx,fy,fz) for set NAME" blocks of a .dat file.
std::map<std::string, std::array<double, 3>> ccx_totals(const fs::path& dat) {
  std::map<std::string, std::array<double, 3>> out;
  std::ifstream in(dat);
  std::string line, name;
  while (std::getline(in, line)) {
    const auto at = line.find("for set ");
    if (line.find("total force") != std::string::npos && at != std::string::npos) {
      std::istringstream(line.substr(at + 8)) >> name;
    } else if (!name.empty() && line.find_first_not_of(" \t\r") != std::string::npos) {
      std::istringstream v(line);
      v >> out[name][0] >> out[name][1] >> out[name][2];
      name.clear();
    }
  }
  return out;
}

bool ccx_on_path() { return std::system("command -v ccx > /dev/null 2>&1") == 0; }

/// CalculiX's RF is the internal force at the constrained dofs; our reaction is internal minus external force, so
/// loads acting right on supported nodes (a pressure on a face that touches the clamp) are part of ours only.
std::array<double, 3> external_on_set(const Model& m, const std::string& set) {
  const Eigen::VectorXd f = external_nodal_load(m, 0);
  std::array<double, 3> sum{0, 0, 0};
  for (const auto& bc : m.displacements)
    if (bc.set == set)
      for (int c = 0; c < m.dim; ++c)
        if (bc.value[c]) {
          sum[c] = 0;
          for (int n : bc.nodes) sum[c] += f[n * m.dim + c];
        }
  return sum;
}

/// Our reactions and CalculiX's on every supported set, to 1e-5 of the largest component.
void expect_same_reactions(const Model& m, const std::string& tag) {
  auto solver = make_solver("direct", {});
  const Results r = run_linear_static(m, *solver);
  const json ours = make_summary(m, r, {}).at("results").at("reactions").at("beam");
  const fs::path dir = fs::temp_directory_path() / ("rollsim-ccx-" + tag + "-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "model.inp") << calculix_input(m);
  const std::string cmd = "cd '" + dir.string() + "' && OMP_NUM_THREADS=1 ccx -i model > ccx.log 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << "ccx failed, see " << dir;
  const auto theirs = ccx_totals(dir / "model.dat");
  ASSERT_EQ(theirs.size(), ours.size()) << dir;
  double scale = 0;
  for (auto it = ours.begin(); it != ours.end(); ++it)
    for (const auto& c : *it) scale = std::max(scale, std::abs(c.get<double>()));
  for (auto it = ours.begin(); it != ours.end(); ++it) {
    const auto& ccx = theirs.at(calculix_set_name(m, 0, it.key()));
    const auto ext = external_on_set(m, it.key());
    for (int c = 0; c < m.dim; ++c)
      EXPECT_NEAR((*it)[c].get<double>(), ccx[c] - ext[c], 1e-5 * scale)
          << tag << " set " << it.key() << " component " << c;
  }
  fs::remove_all(dir);
}

}  // namespace

TEST(CalculixWriter, SameReactionsAsCalculix2D) {
  if (!ccx_on_path()) GTEST_SKIP() << "ccx not on PATH";
  const std::string tip = R"(, {"type": "displacement", "body": "beam", "set": "tip", "uy": 1})";
  const std::string loads = R"(, {"type": "force", "body": "beam", "set": "xmax", "fx": 0.5, "fy": -1})"
                            R"(, {"type": "pressure", "body": "beam", "surface": "ymax", "value": 0.25})";
  expect_same_reactions(cantilever(2, {8, 4, 1}, tip), "2d-tip");
  expect_same_reactions(cantilever(2, {8, 4, 1}, loads), "2d-loads");
  // a body force (CalculiX integrates its BX, BY itself) and a shear traction (written as our nodal forces)
  const std::string body = R"(, {"type": "body_force", "body": "beam", "bx": 0.3, "by": -2})"
                           R"(, {"type": "traction", "body": "beam", "surface": "ymax", "tx": -1, "ty": 0.5})";
  expect_same_reactions(cantilever(2, {8, 4, 1}, body), "2d-body");
}

TEST(CalculixWriter, SameReactionsAsCalculix3D) {
  if (!ccx_on_path()) GTEST_SKIP() << "ccx not on PATH";
  const std::string tip = R"(, {"type": "displacement", "body": "beam", "set": "tip", "uz": 1})";
  const std::string loads = R"(, {"type": "force", "body": "beam", "set": "xmax", "fy": 0.5})"
                            R"(, {"type": "pressure", "body": "beam", "surface": "zmax", "value": 1})"
                            R"(, {"type": "pressure", "body": "beam", "surface": "ymin", "value": 2})";
  expect_same_reactions(cantilever(3, {4, 2, 2}, tip), "3d-tip");
  expect_same_reactions(cantilever(3, {4, 2, 2}, loads), "3d-loads");
  const std::string body = R"(, {"type": "body_force", "body": "beam", "by": 0.4, "bz": -2})"
                           R"(, {"type": "traction", "body": "beam", "surface": "zmax", "tx": -1, "tz": 0.5})";
  expect_same_reactions(cantilever(3, {4, 2, 2}, body), "3d-body");
}

namespace {
Model sample(const std::string& name, const std::string& contact_type = "") {
  Project p = load_project(fs::path(ROLLSIM_SOURCE_DIR) / "samples" / (name + ".json"));
  if (!contact_type.empty()) p.data["contacts"][0]["type"] = contact_type;
  return build_model(p);
}

/// Our normal contact force and CalculiX's total reaction on the base's support (its z component).
std::pair<double, double> contact_forces(const Model& m, const std::string& tag) {
  auto solver = make_solver("direct", {});
  const Results r = run_linear_static(m, *solver);
  const fs::path dir = fs::temp_directory_path() / ("rollsim-ccx-" + tag + "-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "model.inp") << calculix_input(m);
  const std::string cmd = "cd '" + dir.string() + "' && OMP_NUM_THREADS=1 ccx -i model > ccx.log 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << "ccx failed, see " << dir;
  const double theirs = ccx_totals(dir / "model.dat")["N_BASE_ZMIN"][2];
  fs::remove_all(dir);
  return {r.contacts.at(0).normal_force, theirs};
}
}  // namespace

TEST(CalculixWriter, ContactPairsOnElementFaceSurfaces3D) {
  for (const std::string type : {"tied", "frictionless"}) {
    const Model m = sample("block-indent-3d-10x6x4", type);
    const auto lines = lines_of(calculix_input(m));
    const auto base = block_after(lines, "*SURFACE, NAME=S_BASE_ZMAX, TYPE=ELEMENT");
    EXPECT_EQ(base.size(), m.bodies[0].mesh.surfaces.at("zmax").size()) << "one face per facet";
    EXPECT_EQ(base.front().substr(base.front().find(',')), ", S2") << "the top face of a C3D8";
    if (type == "tied") {
      EXPECT_EQ(block_after(lines, "*TIE, NAME=T_BLOCK_BASE, POSITION TOLERANCE=1e-06, ADJUST=NO"),
                std::vector<std::string>{"S_BASE_ZMAX, S_BLOCK_ZMIN"});
    } else {
      EXPECT_EQ(block_after(lines, "*CONTACT PAIR, INTERACTION=I_BLOCK_BASE, TYPE=NODE TO SURFACE, SMALL SLIDING"),
                std::vector<std::string>{"S_BASE_ZMAX, S_BLOCK_ZMIN"});
      EXPECT_EQ(block_after(lines, "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR").size(), 1u);
    }
  }
}

TEST(CalculixWriter, RefusesContactIn2D) {
  try {
    calculix_input(sample("block-indent-2d-50x30"));
    FAIL() << "a 2D contact model exported as unconnected bodies";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("contacts[0] ('block-base')"), std::string::npos) << e.what();
  }
}

TEST(CalculixWriter, SameContactForceAsCalculix3D) {
  if (!ccx_on_path()) GTEST_SKIP() << "ccx not on PATH";
  const auto [tied, ccx_tied] = contact_forces(sample("block-indent-3d-10x6x4"), "tied");
  EXPECT_NEAR(ccx_tied, tied, 1e-5 * tied);
  // a penalty (1e3 E / h) against our exact non-penetration: −8.5 % on 10×6×4, −1.4 % on 20×12×4 (docs/VALIDATION.md)
  const auto [frictionless, ccx_frictionless] = contact_forces(sample("block-indent-3d-20x12x4", "frictionless"), "fl");
  EXPECT_NEAR(ccx_frictionless, frictionless, 0.03 * frictionless);
}

}  // namespace test_calculix_writer
