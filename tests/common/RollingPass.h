#pragma once
// The paper's plane-strain pass as the rolling tests run it: slab 36 × 6 (coarse, so a run takes about a second),
// E 210 GPa, σ_0 100 MPa, sticking friction (no slip), `direct`, over `travel` mm of roll travel.
#include <nlohmann/json.hpp>

namespace testing_support {

inline nlohmann::json paper_pass_2d(double travel, double travel_increment) {
  return {{"name", "pass"},
          {"dimension", 2},
          {"process",
           {{"type", "rolling"},
            {"slab_nx", 36},
            {"slab_nt", 6},
            {"slab_E", 210000.0},
            {"travel", travel},
            {"travel_increment", travel_increment}}},
          {"solver", {{"mode", "direct"}}}};
}

}  // namespace testing_support
