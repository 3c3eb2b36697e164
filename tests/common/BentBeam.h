#pragma once
// A slender finite-strain cantilever (100 × 5, 20 × 2 Q4, steel) bent by its tip 60 down in 4 steps with only 4
// Newton iterations allowed and `max_cutbacks` 1: each full step is cut back once and then converges, so a run
// converges with more cut-backs in all than its limit — the case of the cut-back tests (driver, CLI, window).
#include <nlohmann/json.hpp>

namespace testing_support {

inline nlohmann::json bent_beam(double E = 210000.0, double nu = 0.3) {
  const nlohmann::json mesh = {{"type", "block"}, {"nx", 20}, {"ny", 2}, {"lx", 100.0}, {"ly", 5.0}};
  return {{"name", "beam"},
          {"dimension", 2},
          {"materials", {{{"name", "steel"}, {"E", E}, {"nu", nu}}}},
          {"bodies", {{{"name", "beam"}, {"material", "steel"}, {"kinematics", "finite"}, {"mesh", mesh}}}},
          {"boundary_conditions",
           {{{"type", "displacement"}, {"body", "beam"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}},
            {{"type", "displacement"}, {"body", "beam"}, {"set", "xmax"}, {"uy", -60.0}}}},
          {"analysis", {{"type", "newton"}, {"increments", 4}, {"max_iterations", 4}, {"max_cutbacks", 1}}},
          {"solver", {{"mode", "direct"}}}};
}

}  // namespace testing_support
