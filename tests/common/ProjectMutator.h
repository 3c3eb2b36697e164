#pragma once
// A seeded mutator of project files, shared by the in-process and the binary fuzz tests: structural edits on the
// JSON tree (remove a key, extreme or mistyped values, duplicates, 10000-deep nesting), then byte-level edits.
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

namespace fuzz {

/// Small valid projects (tens of elements, so that solving a mutant is cheap): 2D and 3D, every mesh generator, and
/// partitioned bodies (a structured spelling and an explicit map) under feti.
inline const char* kSeeds[] = {
    R"({"dimension": 2, "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
 "bodies": [{"name": "b", "material": "m", "formulation": "bbar",
   "mesh": {"type": "block", "nx": 4, "ny": 3, "lx": 4, "ly": 3, "origin": [0, 0]},
   "node_sets": [{"name": "tip", "nearest": [4, 3]}, {"name": "edge", "box_min": [4, 0], "box_max": [4, 3]}]},
  {"name": "r", "material": "m", "mesh": {"type": "annulus", "center": [2, 5], "inner_radius": 0.5,
   "outer_radius": 1, "n_radial": 2, "n_around": 8}},
  {"name": "p", "material": "m", "mesh": {"type": "plate_with_hole", "width": 2, "height": 2, "radius": 0.5,
   "n_around": 4, "n_radial": 2, "grading": 1.2}}],
 "boundary_conditions": [{"type": "displacement", "body": "b", "set": "xmin", "ux": 0, "uy": 0},
  {"type": "symmetry", "body": "r", "set": "inner", "normal": "x"},
  {"type": "displacement", "body": "r", "set": "inner", "uy": 0},
  {"type": "symmetry", "body": "p", "set": "left", "normal": "x"},
  {"type": "symmetry", "body": "p", "set": "bottom", "normal": "y"},
  {"type": "displacement", "body": "p", "set": "top", "uy": 0.01},
  {"type": "force", "body": "b", "set": "tip", "fy": -1},
  {"type": "pressure", "body": "b", "surface": "ymax", "value": 2}],
 "solver": {"mode": "skyline", "threads": 1}, "probes": [{"name": "A", "at": [4, 3], "body": "b"}],
 "output": {"vtu": false}})",
    R"({"dimension": 3, "name": "fuzz3d", "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
 "bodies": [{"name": "b", "material": "m", "mesh": {"type": "block", "nx": 2, "ny": 2, "nz": 2, "lx": 2, "ly": 2,
   "lz": 2}, "node_sets": [{"name": "tip", "nearest": [2, 2, 2]},
   {"name": "edge", "box_min": [2, 0, 2], "box_max": [2, 2, 2], "tolerance": 0.001}]},
  {"name": "c", "material": "m", "mesh": {"type": "cylinder", "center": [5, 5], "y0": 0, "length": 1,
   "inner_radius": 0.5, "outer_radius": 1, "n_radial": 1, "n_around": 6, "n_axial": 1, "end_angle": 180}}],
 "boundary_conditions": [{"type": "displacement", "body": "b", "set": "xmin", "ux": 0, "uy": 0, "uz": 0},
  {"type": "displacement", "body": "c", "set": "inner", "ux": 0, "uy": 0, "uz": 0},
  {"type": "force", "body": "b", "set": "edge", "fz": -1}, {"type": "pressure", "body": "c", "surface": "outer",
   "value": 2}],
 "solver": {"mode": "direct"}, "probes": [{"name": "A", "at": [2, 2, 2]}], "output": {"vtu": true}})",
    R"({"dimension": 2, "name": "fuzzfeti", "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
 "bodies": [{"name": "b", "material": "m", "mesh": {"type": "block", "nx": 6, "ny": 4, "lx": 6, "ly": 4},
   "partition": "3x2"},
  {"name": "q", "material": "m", "mesh": {"type": "block", "nx": 4, "ny": 3, "lx": 4, "ly": 3, "origin": [0, 6]},
   "partition_map": [0, 0, 1, 1, 0, 0, 1, 1, 2, 2, 2, 2]}],
 "boundary_conditions": [{"type": "displacement", "body": "b", "set": "xmin", "ux": 0, "uy": 0},
  {"type": "displacement", "body": "q", "set": "xmin", "ux": 0, "uy": 0},
  {"type": "force", "body": "b", "set": "xmax", "fy": -1}, {"type": "force", "body": "q", "set": "xmax", "fx": 1}],
 "solver": {"mode": "feti", "preconditioner": "dirichlet"}, "output": {"vtu": true}})"};

/// Values swapped in for any node of the tree: extremes, wrong types, names that exist elsewhere.
inline const char* kTokens[] = {"-1", "0", "1e308", "-1e308", "1e-308", "5e-324", "2147483648", "4294967297", "1e6",
                                "1000", "0.5", "-0.0", "3", "\"\"", "\"x\"", "\"all\"", "\"b\"", "\"m\"", "\"block\"",
                                "null", "true", "[]", "{}", "[1,2,3]",
                                // partitions: more subdomains than elements, 32-bit overflow, METIS extremes
                                "\"400x400\"", "\"65536x65536\"", "\"metis:0\"", "\"metis:1000000\"", "\"1x1x1\""};

/// Text spliced in anywhere: literals JSON forbids, numbers beyond double, unbalanced brackets.
inline const char* kSplices[] = {"NaN", "Infinity", "-Infinity", "1e400", "-1e400", "\"", ",", "}", "]", "\\u0000"};

/// Numbers swapped in for a number: the extremes of double and of the counts.
inline const double kExtremes[] = {-1, 0, 1e308, -1e308, 1e-308, 5e-324, 1e-200, 1e200, 2147483648.0, 0.4999999};

inline constexpr int kDeep = 10000;  // nesting depth of the deep-nesting mutation

inline size_t pick(std::mt19937& rng, size_t n) { return n ? rng() % n : 0; }

/// Every node of `j` as a JSON pointer (the root excluded).
inline void collect(const nlohmann::json& j, const nlohmann::json::json_pointer& at,
                    std::vector<nlohmann::json::json_pointer>& out) {
  if (!at.empty()) out.push_back(at);
  if (j.is_object())
    for (const auto& [k, v] : j.items()) collect(v, at / k, out);
  if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i) collect(j[i], at / i, out);
}

/// Replaces the first number at or after node `from` (in document order) by an extreme value.
inline void extreme_number(nlohmann::json& j, const std::vector<nlohmann::json::json_pointer>& nodes, size_t from,
                           std::mt19937& rng) {
  for (size_t i = from; i < nodes.size(); ++i) {
    if (!j[nodes[i]].is_number()) continue;
    j[nodes[i]] = kExtremes[pick(rng, std::size(kExtremes))];
    return;
  }
}

/// One edit of the tree; a node replaced by "@DEEP@" becomes 10000-deep nested arrays in the text.
inline void mutate_tree(nlohmann::json& j, std::mt19937& rng) {
  std::vector<nlohmann::json::json_pointer> nodes;
  collect(j, nlohmann::json::json_pointer(), nodes);
  const size_t n = pick(rng, nodes.size());
  const auto at = nodes[n];
  nlohmann::json& parent = j[at.parent_pointer()];
  switch (pick(rng, 6)) {
    case 0:  // remove the key or the array entry
      if (parent.is_object()) parent.erase(at.back());
      if (parent.is_array()) parent.erase(std::stoul(at.back()));
      return;
    case 1:  // duplicate an array entry (duplicate names, extra bodies)
      if (parent.is_array()) parent.push_back(j[at]);
      return;
    case 2:  // deep nesting
      j[at] = "@DEEP@";
      return;
    case 3:  // a number at the edge of double or of the counts
      extreme_number(j, nodes, n, rng);
      return;
    default:  // a value of any type
      j[at] = nlohmann::json::parse(kTokens[pick(rng, std::size(kTokens))]);
  }
}

/// One byte-level edit of the text.
inline void mutate_text(std::string& s, std::mt19937& rng) {
  if (s.empty()) return;
  const size_t at = pick(rng, s.size());
  switch (pick(rng, 5)) {
    case 0:  // byte flip
      s[at] = static_cast<char>(pick(rng, 256));
      return;
    case 1:  // deletion
      s.erase(at, 1 + pick(rng, 20));
      return;
    case 2:  // duplication
      s.insert(at, s.substr(pick(rng, s.size()), 1 + pick(rng, 40)));
      return;
    case 3:  // truncation
      s.resize(at);
      return;
    default:  // text JSON forbids
      s.insert(at, kSplices[pick(rng, std::size(kSplices))]);
  }
}

/// A mutant of `seed`: a quarter get 1-2 text edits only, the rest 1-3 tree edits and sometimes one text edit.
inline std::string mutate(const std::string& seed, std::mt19937& rng) {
  nlohmann::json j = nlohmann::json::parse(seed);
  const bool text_only = pick(rng, 4) == 0;
  const size_t tree = text_only ? 0 : 1 + pick(rng, 3), text = text_only ? 1 + pick(rng, 2) : pick(rng, 4) == 0;
  for (size_t i = 0; i < tree; ++i) mutate_tree(j, rng);
  std::string s = j.dump(pick(rng, 2) ? 1 : -1);
  for (size_t p; (p = s.find("\"@DEEP@\"")) != std::string::npos;)
    s.replace(p, 8, std::string(kDeep, '[') + (pick(rng, 2) ? std::string(kDeep, ']') : ""));
  for (size_t i = 0; i < text; ++i) mutate_text(s, rng);
  return s;
}

}  // namespace fuzz
