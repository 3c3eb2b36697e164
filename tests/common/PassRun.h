#pragma once
// A rolling pass run in process as run_project runs it, with its measures typed beside its generic tables.
#include <nlohmann/json.hpp>
#include <optional>

#include "process/rolling/RollingMeasures.h"
#include "process/rolling/RollingProcess.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunProject.h"

namespace testing_support {

/// A pass's results as run_project gives them (its process's tables in Results::process), and its measures typed
/// (process/rolling's measure_rolling of the same results; none when nothing was solved).
struct PassRun : rollsim::Results {
  std::optional<rollsim::RollingResults> rolling;
};

/// The pass `j` validated, built and run.
inline PassRun run_pass(const nlohmann::json& j) {
  const rollsim::Project p = rollsim::parse_project(j.dump(), "test.json");
  const rollsim::Model m = rollsim::build_model(p);
  PassRun out{rollsim::run_project(p, m, nullptr), std::nullopt};
  if (out.process) out.rolling = rollsim::measure_rolling(rollsim::rolling_pass(p.data.at("process"), m), m, out);
  return out;
}

}  // namespace testing_support
