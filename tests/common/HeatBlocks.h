#pragma once
// The blocks the heat-conduction tests build their projects from: a body of a block mesh, and the supports that hold
// it at rest (xmin in x, ymin in y) so that the heat is what moves.
#include <nlohmann/json.hpp>
#include <string>

namespace testing_support {

/// Body `name` of material `mat`: a block nx × ny of lx × ly whose lower left corner is at (0, y0).
inline nlohmann::json heat_block(const std::string& name, const std::string& mat, int nx, int ny, double lx, double ly,
                                 double y0 = 0) {
  return {{"name", name},
          {"material", mat},
          {"mesh", {{"type", "block"}, {"nx", nx}, {"ny", ny}, {"lx", lx}, {"ly", ly}, {"origin", {0.0, y0}}}}};
}

/// A body held at xmin (x) and ymin (y), nothing else.
inline nlohmann::json held_at_rest(const std::string& body) {
  return nlohmann::json::array({{{"type", "displacement"}, {"body", body}, {"set", "xmin"}, {"ux", 0.0}},
                                {{"type", "displacement"}, {"body", body}, {"set", "ymin"}, {"uy", 0.0}}});
}

}  // namespace testing_support
