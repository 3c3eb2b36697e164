#pragma once
// A seeded text mutator for project files (shared by the in-process and the binary fuzz tests).
#include <random>
#include <string>

namespace fuzz {

inline const char* kSeed = R"({"dimension": 2, "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
 "bodies": [{"name": "b", "material": "m", "formulation": "bbar",
   "mesh": {"type": "block", "nx": 4, "ny": 3, "lx": 4, "ly": 3, "origin": [0, 0]},
   "node_sets": [{"name": "tip", "nearest": [4, 3]}, {"name": "edge", "box_min": [4, 0], "box_max": [4, 3]}]},
  {"name": "r", "material": "m", "mesh": {"type": "annulus", "center": [2, 5], "inner_radius": 0.5,
   "outer_radius": 1, "n_radial": 2, "n_around": 8}}],
 "boundary_conditions": [{"type": "displacement", "body": "b", "set": "xmin", "ux": 0, "uy": 0},
  {"type": "symmetry", "body": "r", "set": "inner", "normal": "x"},
  {"type": "displacement", "body": "r", "set": "inner", "uy": 0},
  {"type": "force", "body": "b", "set": "tip", "fy": -1}, {"type": "pressure", "body": "b", "surface": "ymax", "value": 2}],
 "solver": {"mode": "skyline", "threads": 1}, "probes": [{"name": "A", "at": [4, 3], "body": "b"}],
 "output": {"vtu": false}})";

inline const char* kTokens[] = {"-1",   "0",     "1e308", "-1e308",  "1e-308",    "2147483648", "4294967297",
                                "\"\"", "\"x\"", "null",  "true",    "[]",        "{}",         "[1,2,3]",
                                "0.5",  "-0",    "1e6",   "\"all\"", "\"block\"", "3"};

inline std::string mutate(std::string s, std::mt19937& rng) {
  auto pick = [&](size_t n) { return static_cast<size_t>(std::uniform_int_distribution<size_t>(0, n - 1)(rng)); };
  const int edits = 1 + static_cast<int>(pick(3));
  for (int e = 0; e < edits && !s.empty(); ++e) {
    const size_t at = pick(s.size());
    switch (pick(6)) {
      case 0:
        s[at] = static_cast<char>(pick(128));
        break;  // byte flip
      case 1:
        s.erase(at, 1 + pick(20));
        break;  // deletion
      case 2:
        s.insert(at, s.substr(pick(s.size()), 1 + pick(30)));
        break;  // duplication
      case 3:
        s.resize(at);
        break;   // truncation
      case 4: {  // a number -> an extreme token
        const size_t d = s.find_first_of("0123456789", at);
        if (d != std::string::npos) {
          const size_t end = s.find_first_not_of("0123456789.e-", d);
          s.replace(d, end - d, kTokens[pick(std::size(kTokens))]);
        }
        break;
      }
      default: {  // a string value -> a token
        const size_t q = s.find("\": ", at);
        if (q != std::string::npos) {
          const size_t end = s.find_first_of(",}]", q + 3);
          if (end != std::string::npos) s.replace(q + 3, end - q - 3, kTokens[pick(std::size(kTokens))]);
        }
      }
    }
  }
  return s;
}

}  // namespace fuzz
