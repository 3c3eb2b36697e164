#pragma once
// What `solver.mode: auto` chose and why: every candidate mode's predicted cost (the partition table's cost model,
// partition/PartitionReport.h) and the cheapest. Plain data for summary.json, the progress output and the window.
#include <string>
#include <vector>

namespace rollsim {

/// One candidate weighed by `auto`.
struct ModeCost {
  std::string mode;  // a solver registry name: direct, mixed, feti
  double flops = 0;  // predicted cost [flops]
};

struct AutoChoice {
  std::string mode;             // the candidate of least predicted cost (ties: the earlier one)
  std::vector<ModeCost> costs;  // every candidate, in registry order
  std::string reason;           // one line: the choice and the costs it was made from
  double seconds = 0;           // what choosing cost (the factor estimates) [s]
};

}  // namespace rollsim
