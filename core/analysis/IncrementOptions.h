#pragma once
// The load steps of either analysis (the analysis section's increments and active-set limit), typed, and the table
// that declares them to the project schema.
#include <vector>

#include "base/BoundField.h"
#include "base/SchemaFields.h"

namespace rollsim {

/// The most load increments an analysis takes (the range of analysis.increments).
constexpr int kMaxIncrements = 1000;

struct IncrementOptions {
  int increments = 1;                  // equal proportional steps of every load and prescribed displacement
  int max_active_set_iterations = 50;  // linear: solves an increment's frictionless active-set loop may take
};

inline const std::vector<BoundField<IncrementOptions>>& increment_option_fields() {
  using namespace schema;
  using I = IncrementOptions;
  static const std::vector<BoundField<I>> table = {
      bind(count("increments", "load increments N: equal proportional steps of every load and prescribed displacement",
                 kMaxIncrements),
           &I::increments),
      bind(count("max_active_set_iterations",
                 "linear solves an increment may take while the frictionless contact statuses change; the run ends "
                 "not_converged (iteration_limit) when they still change after that many",
                 1000),
           &I::max_active_set_iterations),
  };
  return table;
}

}  // namespace rollsim
