// Bad input through the real binary, as a specification: every failure class exits with code 2, names where
// (JSON path, or line and column) and why, prints nothing on stdout and writes nothing into the output directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "RunBinary.h"

namespace test_bad_input {

using json = nlohmann::json;
namespace fs = std::filesystem;

/// A bad project, and what its message must name (outside the anonymous namespace: the TEST_P fixture's parameter).
struct Case {
  std::string name;
  std::function<std::string()> text;
  std::string where;
  std::string reason;
};

namespace {

// Valid 2D project; every kind of condition, so that each has a path to break. Line 3 holds the material.
const std::string k2D = R"({
  "dimension": 2,
  "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
  "bodies": [{"name": "b", "material": "m",
              "mesh": {"type": "block", "nx": 4, "ny": 3, "lx": 4, "ly": 3},
              "node_sets": [{"name": "tip", "nearest": [4, 3]}]}],
  "boundary_conditions": [
    {"type": "displacement", "body": "b", "set": "xmin", "ux": 0, "uy": 0},
    {"type": "symmetry", "body": "b", "set": "ymin", "normal": "y"},
    {"type": "force", "body": "b", "set": "tip", "fy": -1},
    {"type": "pressure", "body": "b", "surface": "ymax", "value": 0.5}],
  "solver": {"mode": "direct", "threads": 1},
  "probes": [{"name": "A", "at": [4, 3]}],
  "output": {"vtu": true}
})";

const std::string k3D = R"({
  "dimension": 3,
  "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
  "bodies": [{"name": "b", "material": "m",
              "mesh": {"type": "block", "nx": 2, "ny": 2, "nz": 2, "lx": 2, "ly": 2, "lz": 2},
              "node_sets": [{"name": "tip", "nearest": [2, 2, 2]}]}],
  "boundary_conditions": [
    {"type": "displacement", "body": "b", "set": "xmin", "ux": 0, "uy": 0, "uz": 0},
    {"type": "force", "body": "b", "set": "tip", "fz": -1}],
  "probes": [{"name": "A", "at": [2, 2, 2]}]
})";

const json kPlate = {
    {"type", "plate_with_hole"}, {"width", 4}, {"height", 4}, {"radius", 1}, {"n_around", 4}, {"n_radial", 2}};
const json kAnnulus = {{"type", "annulus"}, {"center", {0, 0}}, {"inner_radius", 1},
                       {"outer_radius", 2}, {"n_radial", 1},    {"n_around", 8}};

const json kCylinder = {{"type", "cylinder"}, {"center", {0, 0}}, {"length", 1},   {"inner_radius", 1},
                        {"outer_radius", 2},  {"n_radial", 1},    {"n_around", 8}, {"n_axial", 1}};

const json kRoundBar = {{"type", "round_bar"}, {"radius", 1}, {"length", 4},
                        {"n_core", 1},         {"n_ring", 1}, {"n_axial", 2}};

/// One bad project: its text, where the message must point (a JSON path, "line L..." or "" for the whole file)
/// and a fragment of the reason.

using Edit = std::function<void(json&)>;

constexpr double kQuick = 5.0;  // seconds: bad input, huge counts included, is refused before any work

Case raw(std::string name, std::string text, std::string where, std::string reason) {
  return {std::move(name), [text] { return text; }, std::move(where), std::move(reason)};
}
/// The 2D project with `from` replaced by `to` in its text (for what JSON values cannot express).
Case subst(std::string name, std::string from, std::string to, std::string where, std::string reason) {
  std::string text = k2D;
  text.replace(text.find(from), from.size(), to);
  return raw(std::move(name), text, std::move(where), std::move(reason));
}
Case edit(std::string name, Edit f, std::string where, std::string reason, const std::string& base = k2D) {
  return {std::move(name),
          [f, base] {
            json j = json::parse(base);
            f(j);
            return j.dump(1);
          },
          std::move(where), std::move(reason)};
}
/// The 2D project with the value at JSON pointer `ptr` replaced.
Case set(std::string name, std::string ptr, json value, std::string where, std::string reason) {
  return edit(
      std::move(name), [ptr, value](json& j) { j[json::json_pointer(ptr)] = value; }, std::move(where),
      std::move(reason));
}
/// The 2D project without the key at JSON pointer `ptr`.
Case drop(std::string name, std::string ptr, std::string where, std::string reason, const std::string& base = k2D) {
  return edit(
      std::move(name),
      [ptr](json& j) {
        const json::json_pointer p(ptr);
        j[p.parent_pointer()].erase(p.back());
      },
      std::move(where), std::move(reason), base);
}
/// `base` with `key` set to `value`.
json with(json base, const std::string& key, json value) {
  base[key] = std::move(value);
  return base;
}
/// The 3D project as a round bar with `key` set to `value` (`mesh` its other fields), refused at
/// `bodies[0].mesh.<key>` for `reason`.
Case bad_round_bar(std::string name, const std::string& key, json value, std::string reason, json mesh = kRoundBar) {
  return edit(
      std::move(name),
      [key, value, mesh](json& j) {
        j["bodies"][0]["mesh"] = with(mesh, key, value);
        j["bodies"][0]["node_sets"] = json::array();
        j["boundary_conditions"] = {{{"type", "displacement"}, {"body", "b"}, {"set", "zmin"}, {"uz", 0}},
                                    {{"type", "symmetry"}, {"body", "b"}, {"set", "xmin"}, {"normal", "x"}},
                                    {{"type", "symmetry"}, {"body", "b"}, {"set", "ymin"}, {"normal", "y"}}};
        j["probes"] = json::array();
      },
      "bodies[0].mesh." + key, std::move(reason), k3D);
}

/// The 2D project with a copy of the first entry of the array at `ptr` appended.
Case again(std::string name, std::string ptr, std::string where, std::string reason) {
  return edit(
      std::move(name),
      [ptr](json& j) {
        json& list = j[json::json_pointer(ptr)];
        list.push_back(list[0]);
      },
      std::move(where), std::move(reason));
}
std::string nested(const std::string& open, const std::string& close, int depth, const std::string& core = "") {
  std::string s;
  for (int i = 0; i < depth; ++i) s += open;
  s += core;
  for (int i = 0; i < depth; ++i) s += close;
  return s;
}

std::vector<Case> syntax_cases() {
  std::vector<Case> c = {
      raw("empty file", "", "line 1, column 1", "not valid JSON"),
      raw("only whitespace", " \n  ", "line 2", "not valid JSON"),
      raw("trailing garbage", k2D + " xyz", "line 15", "not valid JSON"),
      raw("two documents", k2D + k2D, "line 15", "not valid JSON"),
      raw("top level array", "[1, 2]", "", "the top level must be a JSON object"),
      raw("top level string", "\"project\"", "", "the top level must be a JSON object"),
      raw("top level null", "null", "", "the top level must be a JSON object"),
      subst("NaN literal", "1000", "NaN", "line 3", "not valid JSON"),
      subst("Infinity literal", "1000", "Infinity", "line 3", "not valid JSON"),
      subst("minus Infinity literal", "0.3", "-Infinity", "line 3", "not valid JSON"),
      subst("number overflowing double", "1000", "1e400", "line 3", "number 1e400 is beyond the range of a double"),
      subst("negative overflow", "0.3", "-1e400", "line 3", "number -1e400 is beyond the range of a double"),
      subst("single quotes", "\"m\"", "'m'", "line 3", "not valid JSON"),
      subst("comment", "\"dimension\"", "// 2D\n\"dimension\"", "line 2", "not valid JSON"),
      subst("ill-formed UTF-8", "\"tip\"", "\"t\xff\xfe\"", "line 6", "ill-formed UTF-8"),
      subst("control character in a string", "\"tip\"", "\"t\x01p\"", "line 6", "not valid JSON"),
      raw("deep nesting, unclosed", std::string(100000, '['), "line 1, column 65", "nested deeper than 64 levels"),
      subst("deep nesting, closed, in a vector", "[4, 3]}]}]", nested("[", "]", 1000000) + "}]}]", "line 6",
            "nested deeper than 64 levels"),
      subst("deep nesting of objects", "\"dimension\"",
            "\"x\": " + nested("{\"a\": ", "}", 100000, "1") + ", \"dimension\"", "line 2",
            "nested deeper than 64 levels"),
  };
  // cut the valid text at several points, from inside the first key to before the last brace
  for (size_t at :
       {1ul, 5ul, k2D.size() / 8, k2D.size() / 4, k2D.size() / 2, k2D.size() * 3 / 4, k2D.size() - 2, k2D.size() - 1})
    c.push_back(raw("truncated at byte " + std::to_string(at), k2D.substr(0, at), "line", "not valid JSON"));
  return c;
}

std::vector<Case> type_cases() {
  return {
      drop("missing dimension", "/dimension", "dimension", "is required (2 or 3)"),
      set("dimension 4", "/dimension", 4, "dimension", "must be one of 2, 3, got 4"),
      set("dimension as string", "/dimension", "2", "dimension", "must be one of 2, 3, got \"2\""),
      set("fractional dimension", "/dimension", 2.5, "dimension", "got 2.5"),
      set("string for number: E", "/materials/0/E", "1000", "materials[0].E",
          "must be a finite number > 0, got \"1000\""),
      set("string for number: lx", "/bodies/0/mesh/lx", "4", "bodies[0].mesh.lx", "must be a finite number > 0"),
      set("string for number: ux", "/boundary_conditions/0/ux", "0", "boundary_conditions[0].ux", "finite number"),
      set("string in a vector", "/probes/0/at/0", "4", "probes[0].at", "must be an array of 2 finite numbers"),
      set("number for string: body name", "/bodies/0/name", 5, "bodies[0].name", "must be a non-empty string, got 5"),
      set("number for string: condition body", "/boundary_conditions/0/body", 1, "boundary_conditions[0].body",
          "non-empty string"),
      set("empty string for a name", "/materials/0/name", "", "materials[0].name", "must be a non-empty string"),
      set("object for array: bodies", "/bodies", json::object(), "bodies",
          "must be an array of body objects, got an object"),
      set("object for array: conditions", "/boundary_conditions", json::object(), "boundary_conditions",
          "must be an array"),
      set("object for array: node sets", "/bodies/0/node_sets", json::object(), "bodies[0].node_sets",
          "must be an array"),
      set("object for a vector", "/probes/0/at", json::object(), "probes[0].at", "array of 2 finite numbers"),
      set("array for object: mesh", "/bodies/0/mesh", json::array(), "bodies[0].mesh", "must be a mesh object"),
      set("array for object: solver", "/solver", json::array({1}), "solver", "must be a solver object"),
      set("array for object: body", "/bodies/0", json::array(), "bodies[0]", "must be a body object"),
      set("number for object: output", "/output", 1, "output", "must be a output object"),
      set("bool for integer: nx", "/bodies/0/mesh/nx", true, "bodies[0].mesh.nx",
          "must be a positive integer, got true"),
      set("bool for integer: threads", "/solver/threads", false, "solver.threads", "got false"),
      set("bool for number: nu", "/materials/0/nu", true, "materials[0].nu", "finite number"),
      set("string for bool", "/output/vtu", "yes", "output.vtu", "must be true or false, got \"yes\""),
      set("null for number", "/materials/0/E", nullptr, "materials[0].E", "got null"),
      set("null for string", "/bodies/0/material", nullptr, "bodies[0].material", "got null"),
      set("null for array", "/probes", nullptr, "probes", "must be an array"),
  };
}

std::vector<Case> count_cases() {
  const json block = json::parse(k2D)["bodies"][0]["mesh"];
  const Edit huge3d = [](json& j) {
    for (const char* k : {"/bodies/0/mesh/nx", "/bodies/0/mesh/ny", "/bodies/0/mesh/nz"})
      j[json::json_pointer(k)] = 10000;
  };
  const Edit bodies = [](json& j) {
    j["bodies"][0]["mesh"]["nx"] = 4000;
    j["bodies"][0]["mesh"]["ny"] = 3000;
    for (const char* n : {"c", "d", "e"}) {
      j["bodies"].push_back(j["bodies"][0]);
      j["bodies"].back()["name"] = n;
    }
  };
  return {
      set("negative nx", "/bodies/0/mesh/nx", -3, "bodies[0].mesh.nx", "must be a positive integer, got -3"),
      set("zero ny", "/bodies/0/mesh/ny", 0, "bodies[0].mesh.ny", "must be a positive integer, got 0"),
      set("fractional nx", "/bodies/0/mesh/nx", 2.5, "bodies[0].mesh.nx", "must be a positive integer, got 2.5"),
      set("tiny nx", "/bodies/0/mesh/nx", 1e-300, "bodies[0].mesh.nx", "must be a positive integer"),
      set("nx beyond int", "/bodies/0/mesh/nx", 2147483648LL, "bodies[0].mesh.nx", "must be at most 100000"),
      set("nx = ny = 1e6", "/bodies/0/mesh", with(with(block, "nx", 1e6), "ny", 1e6), "bodies[0].mesh.nx",
          "must be at most 100000"),
      set("nx = ny = 1e5", "/bodies/0/mesh", with(with(block, "nx", 100000), "ny", 100000), "bodies",
          "10000000000 elements, more than this build accepts"),
      edit("3D 1e4 cubed", huge3d, "bodies", "1000000000000 elements, more than this build accepts", k3D),
      edit("sum over four bodies", bodies, "bodies", "48000000 elements, more than this build accepts"),
      set("zero threads in the project", "/solver/threads", 0, "solver.threads", "must be a positive integer"),
      set("too many threads", "/solver/threads", 257, "solver.threads", "must be at most 256"),
      set("odd n_around", "/bodies/0/mesh", with(kPlate, "n_around", 5), "bodies[0].mesh.n_around", "must be even"),
      set("one element around a ring", "/bodies/0/mesh", with(kAnnulus, "n_around", 1), "bodies[0].mesh.n_around",
          "too few elements"),
  };
}

std::vector<Case> field_cases() {
  return {
      drop("missing materials", "/materials", "materials", "no material: give `materials` or a `process`"),
      set("no bodies", "/bodies", json::array(), "bodies", "no body: give `bodies` or a `process`"),
      drop("missing E", "/materials/0/E", "materials[0].E", "is required"),
      drop("missing nu", "/materials/0/nu", "materials[0].nu", "is required"),
      drop("missing mesh", "/bodies/0/mesh", "bodies[0].mesh", "is required"),
      drop("missing material of a body", "/bodies/0/material", "bodies[0].material", "is required"),
      drop("missing nx", "/bodies/0/mesh/nx", "bodies[0].mesh.nx", "is required"),
      drop("missing lx", "/bodies/0/mesh/lx", "bodies[0].mesh.lx", "is required"),
      drop("missing mesh type", "/bodies/0/mesh/type", "bodies[0].mesh.type", "must be one of annulus, block"),
      drop("missing condition body", "/boundary_conditions/0/body", "boundary_conditions[0].body", "is required"),
      drop("missing condition set", "/boundary_conditions/0/set", "boundary_conditions[0].set", "is required"),
      drop("missing symmetry normal", "/boundary_conditions/1/normal", "boundary_conditions[1].normal", "is required"),
      drop("missing pressure value", "/boundary_conditions/3/value", "boundary_conditions[3].value", "is required"),
      drop("missing probe position", "/probes/0/at", "probes[0].at", "is required"),
      drop("missing node set name", "/bodies/0/node_sets/0/name", "bodies[0].node_sets[0].name", "is required"),
      set("force without component", "/boundary_conditions/2", {{"type", "force"}, {"body", "b"}, {"set", "tip"}},
          "boundary_conditions[2]", "sets no component (give fx, fy)"),
      set("unknown field nxx", "/bodies/0/mesh/nxx", 3, "bodies[0].mesh.nxx", "unknown field (allowed: nx, ny"),
      set("unknown top-level field", "/bodys", json::array(), "bodys", "unknown field"),
      set("unknown condition field", "/boundary_conditions/0/uxx", 0, "boundary_conditions[0].uxx", "unknown field"),
      set("misspelt E", "/materials/0/e", 1000, "materials[0].e", "unknown field"),
      set("unknown mesh type", "/bodies/0/mesh/type", "sphere", "bodies[0].mesh.type",
          "must be one of annulus, block, cylinder, disk, import, plate_with_hole, round_bar, got \"sphere\""),
      set("z grading in 2D", "/bodies/0/mesh/z_grading", 1.2, "bodies[0].mesh.z_grading", "not allowed in a 2D model"),
      set("unknown condition type", "/boundary_conditions/0/type", "glue", "boundary_conditions[0].type",
          "got \"glue\""),
      set("unknown solver", "/solver/mode", "fast", "solver.mode", "must be one of"),
      set("unknown formulation", "/bodies/0/formulation", "reduced", "bodies[0].formulation",
          "must be one of full, bbar, got \"reduced\""),
      set("unknown material model", "/materials/0/model", "plastic", "materials[0].model", "linear_elastic"),
      set("unknown symmetry normal", "/boundary_conditions/1/normal", "w", "boundary_conditions[1].normal",
          "must be one of x, y, z"),
  };
}

std::vector<Case> dimension_cases() {
  return {
      set("uz in 2D", "/boundary_conditions/0/uz", 0, "boundary_conditions[0].uz", "not allowed in a 2D model"),
      set("fz in 2D", "/boundary_conditions/2/fz", 1, "boundary_conditions[2].fz", "not allowed in a 2D model"),
      set("normal z in 2D", "/boundary_conditions/1/normal", "z", "boundary_conditions[1].normal",
          "must be x or y in a 2D model"),
      set("nz in 2D", "/bodies/0/mesh/nz", 2, "bodies[0].mesh.nz", "not allowed in a 2D model"),
      drop("nz missing in 3D", "/bodies/0/mesh/nz", "bodies[0].mesh.nz", "is required in a 3D model", k3D),
      drop("lz missing in 3D", "/bodies/0/mesh/lz", "bodies[0].mesh.lz", "is required in a 3D model", k3D),
      set("probe with 3 coordinates in 2D", "/probes/0/at", {4, 3, 0}, "probes[0].at",
          "must be an array of 2 finite numbers, got [4,3,0]"),
      edit(
          "probe with 2 coordinates in 3D",
          [](json& j) {
            j["probes"][0]["at"] = {2, 2};
          },
          "probes[0].at", "must be an array of 3 finite numbers", k3D),
      set("nearest with 1 coordinate", "/bodies/0/node_sets/0/nearest", {4}, "bodies[0].node_sets[0].nearest",
          "array of 2 finite numbers"),
      set("origin with 3 coordinates", "/bodies/0/mesh/origin", {0, 0, 0}, "bodies[0].mesh.origin",
          "array of 2 finite numbers"),
      edit(
          "plate with a hole in 3D",
          [](json& j) {
            j["bodies"][0]["mesh"] = kPlate;
            j["bodies"][0]["node_sets"] = json::array();
          },
          "bodies[0].mesh.type", "'plate_with_hole' meshes are 2D only", k3D),
      set("cylinder in 2D", "/bodies/0/mesh", kCylinder, "bodies[0].mesh.type", "'cylinder' meshes are 3D only"),
      set("round bar in 2D", "/bodies/0/mesh", kRoundBar, "bodies[0].mesh.type", "'round_bar' meshes are 3D only"),
  };
}

std::vector<Case> reference_cases() {
  const Edit two_bodies = [](json& j) {
    j["bodies"].push_back(j["bodies"][0]);
    j["bodies"][1]["name"] = "c";
  };
  return {
      set("no such set", "/boundary_conditions/2/set", "tipp", "boundary_conditions[2].set",
          "no node set 'tipp' in body 'b' (available: all, tip, xmax, xmin, ymax, ymin)"),
      set("no such surface", "/boundary_conditions/3/surface", "top", "boundary_conditions[3].surface",
          "no surface 'top' in body 'b' (available: xmax, xmin, ymax, ymin)"),
      set("a node set is no surface", "/boundary_conditions/3/surface", "tip", "boundary_conditions[3].surface",
          "no surface 'tip'"),
      set("no such body in a condition", "/boundary_conditions/0/body", "roll", "boundary_conditions[0].body",
          "no body named 'roll'"),
      set("no such body in a probe", "/probes/0/body", "roll", "probes[0].body", "no body named 'roll'"),
      set("no such material", "/bodies/0/material", "steel", "bodies[0].material", "no material named 'steel'"),
      again("duplicate body", "/bodies", "bodies[1].name", "duplicate name 'b'"),
      again("duplicate material", "/materials", "materials[1].name", "duplicate name 'm'"),
      again("duplicate probe", "/probes", "probes[1].name", "duplicate name 'A'"),
      again("duplicate node set", "/bodies/0/node_sets", "bodies[0].node_sets[1].name", "duplicate name 'tip'"),
      set("node set named like a generated one", "/bodies/0/node_sets/0/name", "xmin", "bodies[0].node_sets[0].name",
          "duplicate name 'xmin': the mesh generator already defines this set"),
      set("node set named all", "/bodies/0/node_sets/0/name", "all", "bodies[0].node_sets[0].name",
          "duplicate name 'all'"),
      set("nearest and box_min", "/bodies/0/node_sets/0/box_min", {0, 0}, "bodies[0].node_sets[0]",
          "give either `nearest` or both `box_min` and `box_max`"),
      set("box_min without box_max", "/bodies/0/node_sets/0", {{"name", "tip"}, {"box_min", {0, 0}}},
          "bodies[0].node_sets[0]", "give either"),
      set("neither nearest nor box", "/bodies/0/node_sets/0", {{"name", "tip"}}, "bodies[0].node_sets[0]",
          "give either"),
      set("box containing no node", "/bodies/0/node_sets/0",
          {{"name", "tip"}, {"box_min", {10, 10}}, {"box_max", {11, 11}}}, "bodies[0].node_sets[0]",
          "the box contains no node"),
      set("negative tolerance", "/bodies/0/node_sets/0",
          {{"name", "tip"}, {"box_min", {4, 0}}, {"box_max", {4, 3}}, {"tolerance", -1}},
          "bodies[0].node_sets[0].tolerance", ">= 0"),
      set("no condition at all", "/boundary_conditions", json::array(), "bodies[0]",
          "body 'b' has no displacement or symmetry condition"),
      edit(
          "only loads",
          [](json& j) {
            auto& bcs = j["boundary_conditions"];
            bcs.erase(bcs.begin(), bcs.begin() + 2);
          },
          "bodies[0]", "body 'b' has no displacement or symmetry condition"),
      edit("second body without support", two_bodies, "bodies[1]",
           "body 'c' has no displacement or symmetry condition"),
      set("only ux on one node", "/boundary_conditions",
          {{{"type", "displacement"}, {"body", "b"}, {"set", "tip"}, {"ux", 0}}}, "bodies[0]",
          "body 'b' is not held against 2 rigid-body mode(s)"),
      set("only one symmetry plane", "/boundary_conditions",
          {{{"type", "symmetry"}, {"body", "b"}, {"set", "xmin"}, {"normal", "x"}}}, "bodies[0]",
          "translation along y"),
  };
}

std::vector<Case> value_cases() {
  return {
      set("name with a slash", "/name", "../../etc", "name", "must be usable as a directory name"),
      set("name dot dot", "/name", "..", "name", "'.' or '..'), got \"..\""),
      set("name with a control character", "/name", "a\tb", "name", "must be usable as a directory name"),
      set("nu = 0.5", "/materials/0/nu", 0.5, "materials[0].nu", "must be a finite number in (-1, 0.5), got 0.5"),
      set("nu = -1", "/materials/0/nu", -1, "materials[0].nu", "in (-1, 0.5)"),
      set("E = 0", "/materials/0/E", 0, "materials[0].E", "must be a finite number > 0, got 0"),
      set("negative E", "/materials/0/E", -1000, "materials[0].E", "> 0"),
      set("zero length", "/bodies/0/mesh/lx", 0, "bodies[0].mesh.lx", "> 0"),
      set("plate radius too big", "/bodies/0/mesh", with(kPlate, "radius", 5), "bodies[0].mesh.radius",
          "must be smaller than width and height"),
      set("inverted ring", "/bodies/0/mesh", with(kAnnulus, "inner_radius", 3), "bodies[0].mesh.inner_radius",
          "must be smaller than outer_radius"),
      set("empty angular span", "/bodies/0/mesh", with(kAnnulus, "end_angle", 0), "bodies[0].mesh.end_angle",
          "must be greater than start_angle"),
      set("grading out of range", "/bodies/0/mesh", with(kPlate, "grading", 3), "bodies[0].mesh.grading", "in [1, 2]"),
      set("cg tolerance 1", "/solver/cg_tolerance", 1, "solver.cg_tolerance", "in (0, 1)"),
      // a project may not make PETSc write files (the reported: -ksp_monitor ascii:PATH replaced PATH)
      set("petsc monitor into a file", "/solver/petsc_options", "-ksp_monitor ascii:/tmp/rollsim-victim",
          "solver.petsc_options", "names the file '/tmp/rollsim-victim': a project may not make PETSc open files"),
      set("petsc log into a file", "/solver/petsc_options", "-log_view :/tmp/rollsim-victim", "solver.petsc_options",
          "names the file '/tmp/rollsim-victim'"),
      // a key given twice: JSON keeps the last silently
      subst("key given twice", "\"E\": 1000, \"nu\": 0.3}", "\"E\": 1000, \"nu\": 0.3, \"E\": 10}", "materials[0].E",
            "is given twice in one object"),
      // the rolling pass's Poisson's ratios (0.5 crashed the slab's update and made the roll's residual NaN)
      edit(
          "rolling slab nu 0.5",
          [](json& j) {
            j = {{"dimension", 2}, {"process", {{"type", "rolling"}, {"slab_nu", 0.5}}}};
          },
          "process.slab_nu", "must be a finite number in (-1, 0.49], got 0.5"),
      edit(
          "rolling roll nu 0.5",
          [](json& j) {
            j = {{"dimension", 2}, {"process", {{"type", "rolling"}, {"roll_nu", 0.5}}}};
          },
          "process.roll_nu", "in (-1, 0.49]"),
      bad_round_bar("round bar taper longer than the bar", "taper_length", 5, "must not exceed length"),
      bad_round_bar("round bar neck too deep", "neck_ratio", 0.3, "in [0.5, 1]"),
      bad_round_bar("round bar neck wider than the bar", "neck_ratio", 1.1, "in [0.5, 1]"),
      bad_round_bar("round bar core too big", "core_fraction", 0.9, "in [0.2, 0.7]"),
      bad_round_bar("round bar without core elements", "n_core", 0, "must be a positive integer, got 0"),
      bad_round_bar("round bar negative radius", "radius", -1, "> 0"),
      bad_round_bar("round bar grading too steep", "axial_grading", 2, "times the smallest",
                    with(kRoundBar, "n_axial", 30)),
  };
}

std::vector<Case> all_cases() {
  std::vector<Case> all;
  for (auto part : {syntax_cases(), type_cases(), count_cases(), field_cases(), dimension_cases(), reference_cases(),
                    value_cases()})
    all.insert(all.end(), part.begin(), part.end());
  return all;
}

/// True if one line of `err` names `where` (a JSON path starts the line; a location is inside it) and `reason`.
bool names_issue(const std::string& err, const std::string& where, const std::string& reason) {
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    const bool path = !where.empty() && where.rfind("line", 0) != 0;
    const bool at = path ? line.rfind("  " + where + ": ", 0) == 0 : line.find(where) != std::string::npos;
    if (at && line.find(reason) != std::string::npos) return true;
  }
  return false;
}

std::string test_name(std::string n) {
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

}  // namespace

class BadInput : public testing::TestWithParam<Case> {};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

TEST_P(BadInput, ExitTwoNamingWhereAndWhyWritingNothing) {
  const Case& c = GetParam();
  const std::string dir = make_temp_dir("bad"), file = dir + "/project.json", out = dir + "/out";
  write_text(file, c.text());
  for (const std::string cmd : {"check", "run"}) {
    std::vector<std::string> args{cmd, file};
    if (cmd == "run") args.insert(args.end(), {"--out", out});  // progress lines may precede the error
    const RunResult r = run_rollsim(args);
    SCOPED_TRACE(cmd + "\n" + r.err);
    EXPECT_FALSE(r.timed_out);
    EXPECT_EQ(r.signal, 0);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_LT(r.seconds, kQuick) << "refusing bad input must be quick";
    EXPECT_NE(r.err.find("rollsim: error: " + file + ": invalid project\n"), std::string::npos);
    EXPECT_TRUE(names_issue(r.err, c.where, c.reason)) << "expected `" << c.where << "`: ... " << c.reason;
  }
  EXPECT_EQ(list_dir(out), std::vector<std::string>{}) << "nothing may be written for invalid input";
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, testing::ValuesIn(all_cases()),
                         [](const auto& p) { return test_name(p.param.name); });

TEST(BadInputFiles, MissingFileDirectoryAndDeviceAreRefused) {
  const std::string dir = make_temp_dir("files");
  for (const std::string& path : {dir + "/nope.json", dir, std::string("/dev/null")}) {
    for (const std::string cmd : {"check", "run"}) {
      const RunResult r = run_rollsim(cmd == "run" ? std::vector<std::string>{cmd, path, "--out", dir + "/out"}
                                                   : std::vector<std::string>{cmd, path});
      SCOPED_TRACE(cmd + " " + path + "\n" + r.err);
      EXPECT_EQ(r.exit_code, 2);
      EXPECT_EQ(r.out, "");
      EXPECT_NE(r.err.find("rollsim: error: " + path + ": invalid project"), std::string::npos);
      EXPECT_NE(r.err.find("no such file (or not a regular file)"), std::string::npos);
    }
  }
  EXPECT_FALSE(fs::exists(dir + "/out"));
  fs::remove_all(dir);
}

/// A command line that must be refused: arguments after `run PROJECT --out DIR`, and a fragment of the message.
struct Cli {
  std::vector<std::string> args;
  std::string expected;
};

TEST(BadInputCli, InvalidOptionValuesAreRefused) {
  const std::string dir = make_temp_dir("cli"), file = dir + "/p.json", out = dir + "/out";
  write_text(file, k2D);
  const std::vector<Cli> table = {
      {{"--solver", "nope"}, "--solver: must be one of skyline, direct, mixed, feti, petsc, auto, got \"nope\""},
      {{"--solver", ""}, "--solver: must be one of"},
      {{"--threads", "0"}, "--threads: must be a positive integer, got 0"},
      {{"--threads", "-1"}, "--threads: must be a positive integer, got -1"},
      {{"--threads", "257"}, "--threads: must be at most 256, got 257"},
      {{"--threads", "abc"}, "--threads: must be a positive integer, got \"abc\""},
      {{"--interface-solver", "cg"}, "--interface-solver: must be one of krylov, dense, got \"cg\""},
      {{"--update", "sometimes"}, "--update: unknown update policy 'sometimes' (valid: always, selective"},
      {{"--set", "solver.threads=0"}, "--set solver.threads: must be a positive integer, got 0"},
      {{"--set", "solver.thread=2"}, "--set solver.thread: unknown field (allowed: "},
      {{"--set", "bodies[7].partition=2x2"}, "--set: bodies[7].partition: no such array item in the project"},
      {{"--set", "solver..mode=direct"}, "--set: 'solver..mode' is not a field path"},
      {{"--set", "bodies[99999999999999999999].partition=2x2"},
       "--set: bodies[99999999999999999999].partition: no such"},
      {{"--set", "solver.threads"}, "--set: expects PATH=VALUE, got 'solver.threads'"},
      {{"--threads", "1e3"}, "--threads"},
      {{"--threads", "99999999999999999999"}, "--threads"},
      {{"--threads"}, "--threads"},
      {{"--bogus"}, "--bogus"},
      {{"extra.json"}, "extra.json"},
  };
  for (const Cli& c : table) {
    std::vector<std::string> args{"run", file, "--out", out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const RunResult r = run_rollsim(args);
    SCOPED_TRACE(testing::PrintToString(c.args) + "\n" + r.err);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find(c.expected), std::string::npos);
  }
  for (const std::vector<std::string>& args : {std::vector<std::string>{"run"}, {"check"}, {"frobnicate"}}) {
    const RunResult r = run_rollsim(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << "\n" << r.err;
    EXPECT_EQ(r.out, "");
  }
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

TEST(BadInputOutput, UnusableOutputDirectoryIsRefused) {
  const std::string dir = make_temp_dir("outdir"), file = dir + "/p.json";
  write_text(file, k2D);
  write_text(dir + "/a-file", "x");
  RunResult r = run_rollsim({"run", file, "--out", dir + "/a-file", "--quiet"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("rollsim: error: cannot create output directory " + dir + "/a-file"), std::string::npos)
      << r.err;
  fs::create_directories(dir + "/out/summary.json");  // a directory where the summary should go
  r = run_rollsim({"run", file, "--out", dir + "/out", "--quiet"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.signal, 0);
  EXPECT_NE(r.err.find("rollsim: error: cannot write into the output folder " + dir +
                       "/out (checked before the "
                       "analysis)"),
            std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

/// A project that passes validation but cannot be solved: the run exits 2 with a message and a summary saying so.
struct Unsolvable {
  std::string name;
  std::string ptr;  // JSON pointer into the 2D project
  json value;
  std::vector<std::string> expected;  // fragments of stderr
};

TEST(BadInputUnsolvable, ExitTwoWithAnErrorSummaryAndNoNaN) {
  const std::vector<Unsolvable> table = {
      {"E at the smallest double (singular stiffness)",
       "/materials/0/E",
       5e-324,
       {"the stiffness matrix is singular at body 'b', node ", "component"}},
      {"prescribed displacement 1e308",
       "/boundary_conditions/0/ux",
       1e308,
       {"bodies[0]: the results of body 'b' are not finite numbers"}},
      {"force -1e308", "/boundary_conditions/2/fy", -1e308, {"bodies[0]: the results of body 'b' are not finite"}},
      {"pressure 1e308", "/boundary_conditions/3/value", 1e308, {"bodies[0]: the results of body 'b' are not finite"}},
      {"length 1e-308", "/bodies/0/mesh/lx", 1e-308, {"body 'b'"}},
  };
  for (const Unsolvable& c : table) {
    SCOPED_TRACE(c.name);
    json j = json::parse(k2D);
    j[json::json_pointer(c.ptr)] = c.value;
    const std::string dir = make_temp_dir("unsolvable"), file = dir + "/p.json", out = dir + "/out";
    write_text(file, j.dump(1));
    EXPECT_EQ(run_rollsim({"check", file}).exit_code, 0) << "the case should pass validation";
    const RunResult r = run_rollsim({"run", file, "--out", out, "--quiet"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("rollsim: error: ", 0), 0u) << r.err;
    for (const auto& f : c.expected) EXPECT_NE(r.err.find(f), std::string::npos) << f << "\n" << r.err;
    EXPECT_EQ(list_dir(out), std::vector<std::string>{"summary.json"}) << "no result.vtu, no temporary file";
    const std::string text = read_text(out + "/summary.json");
    const json summary = json::parse(text);
    EXPECT_EQ(summary["status"], "error");
    EXPECT_FALSE(summary.contains("results"));
    EXPECT_NE(summary.value("message", std::string()), "");
    for (const char* bad : {"NaN", "nan", "Infinity", "inf", "null"})
      EXPECT_EQ(text.find(bad), std::string::npos) << bad;
    fs::remove_all(dir);
  }
}

class Sample : public testing::TestWithParam<std::string> {};

TEST_P(Sample, ChecksValid) {
  const RunResult r = run_rollsim({"check", GetParam()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find(": valid ("), std::string::npos) << r.out;
}

INSTANTIATE_TEST_SUITE_P(Samples, Sample, testing::ValuesIn([] {
                           std::vector<std::string> files;
                           for (const auto& e : fs::directory_iterator(std::string(ROLLSIM_SOURCE_DIR) + "/samples"))
                             if (e.path().extension() == ".json") files.push_back(e.path().string());
                           std::sort(files.begin(), files.end());
                           return files;
                         }()),
                         [](const auto& p) { return test_name(fs::path(p.param).stem().string()); });

TEST(GoodInput, TinyProjectsRunToConvergedResults) {
  for (const std::string& base : {k2D, k3D}) {
    const std::string dir = make_temp_dir("good"), file = dir + "/p.json", out = dir + "/out";
    write_text(file, base);
    const RunResult r = run_rollsim({"run", file, "--out", out});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, out + "/summary.json\n");
    EXPECT_NE(r.err.find("results in " + out), std::string::npos) << r.err;
    EXPECT_EQ(list_dir(out), (std::vector<std::string>{"result.vtu", "summary.json"}));
    const std::string text = read_text(out + "/summary.json");
    EXPECT_EQ(json::parse(text)["status"], "converged");
    EXPECT_EQ(text.find("null"), std::string::npos);
    EXPECT_GT(fs::file_size(out + "/result.vtu"), 1000u);
    fs::remove_all(dir);
  }
}

}  // namespace test_bad_input
