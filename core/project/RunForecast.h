#pragma once
// What a run will be and cost, known before it is solved: its process's facts (a pass: bite angle, contact length,
// whether it bites), its size (dofs, elements), the increments and Newton iterations it is expected to take, and the
// time those are predicted to cost on this kind of machine. The time comes from the partition table's cost model
// (the Cholesky factor of every body, estimated by partition/PartitionReport) and rates measured on the samples
// (docs/BENCHMARKS.md, "The run forecast"): an order of magnitude to plan by, not a promise. `rollsim check` prints
// it, the window shows it beside the solver's settings.
#include <string>
#include <vector>

#include "base/RunStatus.h"
#include "model/Model.h"
#include "process/Process.h"
#include "project/RunConfig.h"

namespace rollsim {

struct RunForecast {
  std::vector<ProcessFact> facts;  // the process's own (empty without one)
  RunStatus refusal;               // the process's refusal (no_bite): nothing will be solved
  long dofs = 0;                   // unknowns of the bodies (prescribed ones excluded)
  long elements = 0;
  bool linear = false;               // a linear analysis: its iterations are solves
  int increments = 0;                // expected: analysis.increments × the process's expected share
  double iterations = 0;             // expected Newton iterations (linear analysis: solves) over the run
  double factor_flops = 0;           // one factorization of every body [flop]
  double seconds_per_iteration = 0;  // predicted: element tangents and factorizations of one iteration [s]
  double seconds = 0;                // predicted for the whole run [s]
};

/// The forecast of running `model` (built from the project `config` was read from).
RunForecast forecast_run(const RunConfig& config, const Model& model);

/// One line: "2273 dofs, factors of 3.1 Mflop, 50 increments, about 300 Newton iterations: about 12 s".
std::string forecast_line(const RunForecast& f);

}  // namespace rollsim
