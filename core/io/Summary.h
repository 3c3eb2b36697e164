#pragma once
// summary.json: status, model counts, solver statistics, timings and key results of a run.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/Results.h"
#include "model/Model.h"

namespace rollsim {

struct RunInfo {
  std::string project;    // project name
  std::string mode;       // solver strategy name (auto: the one it chose)
  nlohmann::json config;  // the resolved run configuration (project/RunConfig's to_json): echoed as `config`
  std::string blas;       // the BLAS library found at run time
  // DGEMM's rate on this machine with the factorizations' thread count (base/DgemmPeak.h; 0: not measured) and
  // what measuring it cost
  double dgemm_peak_gflops = 0, peak_probe_s = 0;
  std::vector<std::string> fields = {};  // output.fields: the arrays result.vtu holds (empty: every one)
  nlohmann::json run = {};               // which run made the results (io/RunFolder's RunStamp): echoed as `run`
};

nlohmann::json make_summary(const Model& model, const Results& results, const RunInfo& run);

}  // namespace rollsim
