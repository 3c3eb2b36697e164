// Bad input through the real binary: every failure class gets exit code 2, a message naming the
// JSON path (or the file) and the reason, nothing on stdout and nothing written to the output dir.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const char* kValid = R"({
  "dimension": 2,
  "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
  "bodies": [{"name": "b", "material": "m",
              "mesh": {"type": "block", "nx": 4, "ny": 3, "lx": 4, "ly": 3},
              "node_sets": [{"name": "tip", "nearest": [4, 3]}]}],
  "boundary_conditions": [
    {"type": "displacement", "body": "b", "set": "xmin", "ux": 0, "uy": 0},
    {"type": "displacement", "body": "b", "set": "tip", "uy": 0.1}],
  "probes": [{"name": "A", "at": [4, 3]}]
})";

struct Case {
  std::string name;
  std::function<std::string()> text;  // the project file content
  std::vector<std::string> expected;  // fragments of stderr
};

Case edit(std::string name, std::function<void(json&)> f, std::vector<std::string> expected) {
  return {std::move(name),
          [f] {
            json j = json::parse(kValid);
            f(j);
            return j.dump(1);
          },
          std::move(expected)};
}
Case raw(std::string name, std::string text, std::vector<std::string> expected) {
  return {std::move(name), [text] { return text; }, std::move(expected)};
}
std::string cut(size_t n) { return std::string(kValid).substr(0, n); }

std::vector<Case> cases() {
  json big3d = json::parse(kValid);
  return {
      raw("empty file", "", {"not valid JSON", "line 1"}),
      raw("truncated early", cut(40), {"not valid JSON"}),
      raw("truncated middle", cut(200), {"not valid JSON"}),
      raw("truncated late", cut(std::string(kValid).size() - 2), {"not valid JSON"}),
      raw("trailing garbage", std::string(kValid) + " xyz", {"not valid JSON"}),
      raw("top level array", "[1, 2]", {"top level must be a JSON object"}),
      raw("NaN literal", R"({"dimension": 2, "x": NaN})", {"not valid JSON"}),
      raw("Infinity literal", R"({"dimension": 2, "x": Infinity})", {"not valid JSON"}),
      raw("number overflow", R"({"dimension": 2, "materials": [{"name": "m", "E": 1e400, "nu": 0.3}]})",
          {"not valid JSON"}),
      raw("deep nesting", std::string(100000, '['), {"error"}),
      edit("missing dimension", [](json& j) { j.erase("dimension"); }, {"dimension", "required"}),
      edit("dimension 4", [](json& j) { j["dimension"] = 4; }, {"dimension", "must be one of 2, 3"}),
      edit("negative nx", [](json& j) { j["bodies"][0]["mesh"]["nx"] = -3; },
           {"bodies[0].mesh.nx: must be a positive integer, got -3"}),
      edit("zero ny", [](json& j) { j["bodies"][0]["mesh"]["ny"] = 0; }, {"bodies[0].mesh.ny", "positive integer"}),
      edit("fractional nx", [](json& j) { j["bodies"][0]["mesh"]["nx"] = 2.5; }, {"bodies[0].mesh.nx", "2.5"}),
      edit("string for number", [](json& j) { j["materials"][0]["E"] = "1000"; },
           {"materials[0].E", "finite number", "\"1000\""}),
      edit("number for string", [](json& j) { j["bodies"][0]["name"] = 5; }, {"bodies[0].name", "string"}),
      edit("object for array", [](json& j) { j["bodies"] = json::object(); }, {"bodies", "array"}),
      edit("array for object", [](json& j) { j["bodies"][0]["mesh"] = json::array(); }, {"bodies[0].mesh"}),
      edit("bool for integer", [](json& j) { j["bodies"][0]["mesh"]["nx"] = true; }, {"bodies[0].mesh.nx"}),
      edit("huge 2D counts",
           [](json& j) { j["bodies"][0]["mesh"]["nx"] = 100000, j["bodies"][0]["mesh"]["ny"] = 100000; },
           {"bodies", "elements, more than this build accepts"}),
      edit("count beyond range", [](json& j) { j["bodies"][0]["mesh"]["nx"] = 1e12; }, {"bodies[0].mesh.nx"}),
      edit("huge 3D counts",
           [](json& j) {
             j["dimension"] = 3;
             j["bodies"][0]["mesh"] = {{"type", "block"}, {"nx", 10000}, {"ny", 10000}, {"nz", 10000},
                                       {"lx", 1},         {"ly", 1},     {"lz", 1}};
             j["bodies"][0]["node_sets"] = json::array();
             j["boundary_conditions"] = json::array();
             j["probes"] = json::array();
           },
           {"more than this build accepts"}),
      edit("sum over bodies too large",
           [](json& j) {
             json b = j["bodies"][0];
             b["mesh"]["nx"] = 4000, b["mesh"]["ny"] = 3000;
             for (int i = 0; i < 3; ++i) {
               b["name"] = "b" + std::to_string(i);
               j["bodies"].push_back(b);
             }
           },
           {"more than this build accepts"}),
      edit("missing required", [](json& j) { j["materials"][0].erase("E"); }, {"materials[0].E", "required"}),
      edit("unknown field", [](json& j) { j["bodies"][0]["mesh"]["nxx"] = 3; },
           {"bodies[0].mesh.nxx", "unknown field"}),
      edit("unknown mesh type", [](json& j) { j["bodies"][0]["mesh"]["type"] = "sphere"; },
           {"bodies[0].mesh.type", "block", "sphere"}),
      edit("unknown bc type", [](json& j) { j["boundary_conditions"][0]["type"] = "glue"; },
           {"boundary_conditions[0].type", "glue"}),
      edit("uz in 2D", [](json& j) { j["boundary_conditions"][0]["uz"] = 0; },
           {"boundary_conditions[0].uz", "not allowed in a 2D model"}),
      edit("nz missing in 3D",
           [](json& j) {
             j["dimension"] = 3;
             j["bodies"][0]["mesh"]["lz"] = 1;
             j["bodies"][0]["node_sets"] = json::array();
             j["probes"] = json::array();
           },
           {"bodies[0].mesh.nz", "required in a 3D model"}),
      edit("probe of wrong length",
           [](json& j) {
             j["probes"][0]["at"] = {1, 2, 3};
           },
           {"probes[0].at", "array of 2 finite numbers"}),
      edit("no such set", [](json& j) { j["boundary_conditions"][1]["set"] = "tipp"; },
           {"boundary_conditions[1].set", "no node set 'tipp'", "available"}),
      edit(
          "no such surface",
          [](json& j) {
            j["boundary_conditions"].push_back({{"type", "pressure"}, {"body", "b"}, {"surface", "top"}, {"value", 1}});
          },
          {"boundary_conditions[2].surface", "no surface 'top'"}),
      edit("no such body", [](json& j) { j["boundary_conditions"][0]["body"] = "roll"; },
           {"boundary_conditions[0].body", "no body named 'roll'"}),
      edit("no such material", [](json& j) { j["bodies"][0]["material"] = "steel"; },
           {"bodies[0].material", "no material named 'steel'"}),
      edit("duplicate body", [](json& j) { j["bodies"].push_back(j["bodies"][0]); }, {"bodies[1].name", "duplicate"}),
      edit("set with nearest and box",
           [](json& j) {
             j["bodies"][0]["node_sets"][0]["box_min"] = {0, 0};
           },
           {"bodies[0].node_sets[0]", "either"}),
      edit("empty box",
           [](json& j) {
             j["bodies"][0]["node_sets"][0] = {{"name", "tip"}, {"box_min", {10, 10}}, {"box_max", {11, 11}}};
           },
           {"bodies[0].node_sets[0]", "no node"}),
      edit("nu = 0.5", [](json& j) { j["materials"][0]["nu"] = 0.5; }, {"materials[0].nu", "(-1, 0.5)"}),
      edit("E = 0", [](json& j) { j["materials"][0]["E"] = 0; }, {"materials[0].E", "> 0"}),
      edit("no component", [](json& j) { j["boundary_conditions"][1].erase("uy"); },
           {"boundary_conditions[1]", "sets no component"}),
      edit("unsupported body", [](json& j) { j["boundary_conditions"] = json::array(); },
           {"bodies[0]", "body 'b'", "rigid body"}),
      edit("plate radius too big",
           [](json& j) {
             j["bodies"][0]["mesh"] = {{"type", "plate_with_hole"},
                                       {"width", 1},
                                       {"height", 1},
                                       {"radius", 2},
                                       {"n_around", 4},
                                       {"n_radial", 2}};
             j["bodies"][0]["node_sets"] = json::array();
             j["boundary_conditions"] = {{{"type", "symmetry"}, {"body", "b"}, {"set", "left"}, {"normal", "x"}}};
           },
           {"bodies[0].mesh.radius", "smaller"}),
  };
}

class BadInput : public testing::TestWithParam<Case> {};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

}  // namespace

TEST_P(BadInput, ExitTwoWithPathAndNoOutput) {
  const Case& c = GetParam();
  const std::string dir = make_temp_dir("bad");
  const std::string file = dir + "/project.json", out = dir + "/out";
  std::ofstream(file) << c.text();
  for (const char* cmd : {"check", "run"}) {
    std::vector<std::string> args{cmd, file};
    if (std::string(cmd) == "run") args.insert(args.end(), {"--out", out, "--quiet"});
    const RunResult r = run_rollsim(args);
    EXPECT_FALSE(r.timed_out) << cmd;
    EXPECT_EQ(r.signal, 0) << cmd;
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.err;
    EXPECT_EQ(r.out, "") << cmd;
    for (const auto& fragment : c.expected)
      EXPECT_NE(r.err.find(fragment), std::string::npos) << fragment << "\n" << r.err;
  }
  EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << "output written for invalid input";
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, testing::ValuesIn(cases()), [](const auto& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
});

TEST(BadInputFiles, MissingFileAndDirectory) {
  const std::string dir = make_temp_dir("missing");
  for (const std::string& path : {dir + "/nope.json", dir}) {
    const RunResult r = run_rollsim({"run", path, "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  }
  fs::remove_all(dir);
}

TEST(BadInputCli, InvalidOptions) {
  const std::string sample = std::string(ROLLSIM_SOURCE_DIR) + "/samples/plate-hole-2d.json";
  const std::string out = make_temp_dir("cli");
  struct Cli {
    std::vector<std::string> args;
    std::string expected;
  };
  for (const Cli& c : {Cli{{"--solver", "nope"}, "unknown solver 'nope' (valid: skyline, direct"},
                       Cli{{"--threads", "0"}, "--threads"}, Cli{{"--threads", "abc"}, "threads"}}) {
    std::vector<std::string> args{"run", sample, "--out", out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const RunResult r = run_rollsim(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
  }
  EXPECT_TRUE(fs::is_empty(out));
  fs::remove_all(out);
}

TEST(BadInputSingular, MechanismNamesTheBodyAndItsFreeModes) {
  json j = json::parse(kValid);
  j["bodies"][0]["node_sets"][0] = {{"name", "pin"}, {"nearest", {0, 0}}};
  j["boundary_conditions"] = {{{"type", "displacement"}, {"body", "b"}, {"set", "pin"}, {"ux", 0}}};
  const std::string dir = make_temp_dir("singular");
  std::ofstream(dir + "/p.json") << j.dump();
  const RunResult r = run_rollsim({"run", dir + "/p.json", "--out", dir + "/out", "--quiet"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  for (const char* f :
       {"bodies[0]", "body 'b' is not held against 2 rigid-body mode(s)", "translation along y", "rotation about z"})
    EXPECT_NE(r.err.find(f), std::string::npos) << f << "\n" << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out/summary.json"));
  fs::remove_all(dir);
}

TEST(GoodInput, EverySampleChecksAndTinyProjectRuns) {
  for (const auto& e : fs::directory_iterator(std::string(ROLLSIM_SOURCE_DIR) + "/samples")) {
    const RunResult r = run_rollsim({"check", e.path().string()});
    EXPECT_EQ(r.exit_code, 0) << e.path() << r.err;
  }
  const std::string dir = make_temp_dir("good");
  std::ofstream(dir + "/p.json") << kValid;
  const RunResult r = run_rollsim({"run", dir + "/p.json", "--out", dir + "/out"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("results in"), std::string::npos);
  EXPECT_EQ(json::parse(std::ifstream(dir + "/out/summary.json"))["status"], "converged");
  EXPECT_TRUE(fs::exists(dir + "/out/result.vtu"));
  fs::remove_all(dir);
}
