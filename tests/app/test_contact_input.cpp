// Bad contact and partition input through the real binary: exit code 2 and a message naming where and why —
// from validation (`check` and `run`, nothing written) or, for what only the geometry or the solver can tell
// (surfaces that never meet, a floating body under `skyline`, contact that cannot hold a body), from `run` with an
// error summary and no result.vtu.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_contact_input {

using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

// A block resting on a base, tied; the block is held only by the contact (a floating body).
const char* kContact = R"({
  "name": "contact-input",
  "dimension": 2,
  "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
  "bodies": [
    {"name": "base", "material": "m", "mesh": {"type": "block", "nx": 6, "ny": 3, "lx": 6, "ly": 3}},
    {"name": "block", "material": "m", "mesh": {"type": "block", "nx": 2, "ny": 1, "lx": 2, "ly": 1, "origin": [2, 3]}}],
  "contacts": [{"name": "c", "type": "tied", "slave_body": "base", "slave_surface": "ymax",
                "master_body": "block", "master_surface": "ymin"}],
  "boundary_conditions": [
    {"type": "displacement", "body": "base", "set": "ymin", "ux": 0, "uy": 0},
    {"type": "force", "body": "block", "set": "ymax", "fy": -1}]
})";

struct Case {
  std::string name, ptr;
  json value;
  std::string where, reason;
};

json edited(const Case& c) {
  json j = json::parse(kContact);
  if (c.value.is_null())
    j[json::json_pointer(c.ptr).parent_pointer()].erase(json::json_pointer(c.ptr).back());
  else
    j[json::json_pointer(c.ptr)] = c.value;
  return j;
}
}  // namespace

TEST(ContactInput, ValidationNamesThePathAndReason) {
  const std::vector<Case> cases = {
      {"no such slave surface", "/contacts/0/slave_surface", "top", "contacts[0].slave_surface",
       "no surface 'top' in body 'base'"},
      {"no such master body", "/contacts/0/master_body", "roll", "contacts[0].master_body", "no body named 'roll'"},
      {"same body twice", "/contacts/0/master_body", "base", "contacts[0]", "slave and master are the same body"},
      {"unknown contact type", "/contacts/0/type", "glued", "contacts[0].type", "must be one of tied, frictionless"},
      {"bad partition spelling", "/bodies/0/partition", "4by4", "bodies[0].partition", "4by4"},
      {"partition map of the wrong length", "/bodies/0/partition_map", json::array({0, 1}), "bodies[0].partition_map",
       "2"},
      {"negative subdomain id", "/bodies/0/partition_map",
       json::array({0, 0, 0, -1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}), "bodies[0].partition_map[3]",
       "must be a subdomain id"},
      {"more METIS parts than elements", "/bodies/1/partition", "metis:9", "bodies[1].partition", "metis:9"},
      {"a turning master without large sliding",
       "/contacts/0/master_turns",
       {{"center", {3, -10}}, {"angle", 5}},
       "contacts[0].sliding",
       "a turning master surface (master_turns) needs large sliding"},
      {"a turning master's axis in 2D",
       "/contacts/0/master_turns",
       {{"center", {3, -10}}, {"angle", 5}, {"axis", {0, 0, 1}}},
       "contacts[0].master_turns.axis",
       "not allowed in a 2D model"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string dir = make_temp_dir("contact"), file = dir + "/p.json", out = dir + "/out";
    write_text(file, edited(c).dump(1));
    for (const std::string cmd : {"check", "run"}) {
      std::vector<std::string> args{cmd, file};
      if (cmd == "run") args.insert(args.end(), {"--out", out, "--quiet"});
      const RunResult r = run_rollsim(args);
      EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.err;
      EXPECT_NE(r.err.find("  " + c.where + ": "), std::string::npos) << cmd << "\n" << r.err;
      EXPECT_NE(r.err.find(c.reason), std::string::npos) << cmd << "\n" << r.err;
    }
    EXPECT_FALSE(fs::exists(out + "/summary.json")) << "nothing written for invalid input";
    fs::remove_all(dir);
  }
}

TEST(ContactInput, UnsolvableContactGivesAnErrorSummary) {
  const std::vector<std::tuple<std::string, json, std::vector<std::string>, std::string>> cases = {
      {"surfaces that never meet",
       json::parse(R"({"ptr": "/bodies/1/mesh/origin", "value": [2, 3.5]})"),
       {},
       "the surfaces never meet"},
      {"floating body under skyline",
       json::parse(R"({"ptr": "/solver", "value": {"mode": "skyline"}})"),
       {},
       "cannot factor a floating body (3 rigid modes"},
      {"frictionless contact cannot hold the block sideways",
       json::parse(R"({"ptr": "/contacts/0/type", "value":
       "frictionless"})"),
       {"--solver", "mixed"},
       "the contact constraints do not hold the floating bodies"},
      {"the same under direct",
       json::parse(R"({"ptr": "/contacts/0/type", "value": "frictionless"})"),
       {"--solver", "direct"},
       "the contact constraints do not hold the floating bodies"},
  };
  for (const auto& [name, edit, extra, reason] : cases) {
    SCOPED_TRACE(name);
    json j = json::parse(kContact);
    j[json::json_pointer(edit["ptr"].get<std::string>())] = edit["value"];
    const std::string dir = make_temp_dir("unsolvable-contact"), file = dir + "/p.json", out = dir + "/out";
    write_text(file, j.dump(1));
    EXPECT_EQ(run_rollsim({"check", file}).exit_code, 0) << "valid input: only solving can tell";
    std::vector<std::string> args{"run", file, "--out", out, "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_rollsim(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("rollsim: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    EXPECT_EQ(list_dir(out), std::vector<std::string>{"summary.json"}) << "no result.vtu";
    EXPECT_EQ(json::parse(read_text(out + "/summary.json"))["status"], "error");
    fs::remove_all(dir);
  }
}

TEST(ContactInput, FloatingBlockSolvesUnderDirectMixedAndFeti) {
  const std::string dir = make_temp_dir("floating"), file = dir + "/p.json";
  json j = json::parse(kContact);
  j["bodies"][0]["partition"] = "3x1";
  write_text(file, j.dump(1));
  double fy[3];
  int k = 0;
  for (const std::string mode : {"direct", "mixed", "feti"}) {
    const std::string out = dir + "/" + mode;
    const RunResult r =
        run_rollsim({"run", file, "--solver", mode, "--out", out, "--quiet", "--cg-tolerance", "1e-10"});
    ASSERT_EQ(r.exit_code, 0) << mode << "\n" << r.err;
    const json s = json::parse(read_text(out + "/summary.json"));
    EXPECT_EQ(s["model"]["rigid_modes"].get<int>(), 3) << mode << ": the block floats, every base piece is held";
    fy[k++] = s["results"]["contact"]["c"]["normal_force"].get<double>();
  }
  EXPECT_NEAR(fy[0], 3.0, 1e-9) << "the block's 3 top nodes push with 1 each";
  EXPECT_NEAR(fy[1], fy[0], 1e-8);
  EXPECT_NEAR(fy[2], fy[0], 1e-8);
  fs::remove_all(dir);
}

// export-ccx wrote a 2D contact project as unconnected bodies with exit 0; now it refuses (exit 2, the pair named,
// no file), and a 3D contact project is written with its pair.
TEST(ContactInput, ExportCcxRefuses2DContactAndWrites3DPairs) {
  const std::string dir = make_temp_dir("export");
  const RunResult two =
      run_rollsim({"export-ccx", ROLLSIM_SOURCE_DIR "/samples/block-indent-2d-50x30.json", dir + "/two.inp"});
  EXPECT_EQ(two.exit_code, 2) << two.err;
  EXPECT_NE(two.err.find("contacts[0] ('block-base')"), std::string::npos) << two.err;
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{}) << "nothing written";
  const RunResult three =
      run_rollsim({"export-ccx", ROLLSIM_SOURCE_DIR "/samples/block-indent-3d-10x6x4.json", dir + "/three.inp"});
  EXPECT_EQ(three.exit_code, 0) << three.err;
  EXPECT_NE(read_text(dir + "/three.inp").find("\n*TIE, NAME=T_BLOCK_BASE"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace test_contact_input
