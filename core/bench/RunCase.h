#pragma once
// One benchmark case run in this process: the project parsed and built, the mesh distorted when asked, the analysis
// timed, the answer checked for finiteness and measured; never throws — every failure becomes a status and words.
#include <limits>
#include <string>

#include "bench/SuiteCase.h"

namespace rollsim::bench {

struct CaseOutcome {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  // converged, not_converged, diverged, error (refused or unsolvable), non_finite (a NaN or Inf in a converged
  // answer), crashed (a signal), timeout — the first four are RunStatus's words
  std::string status = "error";
  std::string message;       // the run's own words for anything but converged
  double wall_s = nan;       // the analysis (run_project): assembly, factorizations, solves, recovery
  double peak_rss_mb = nan;  // the case's process, high-water mark (set by the isolated runner)
  long dofs = 0, multipliers = 0, subdomains = 0, rigid_modes = 0, cg_iterations = 0, factorizations = 0;
  int newton_iterations = 0, active_set_iterations = 0;
  double value = nan, exact = nan;  // the measured quantity and its closed form (NaN: none)
  double solver_error = nan;        // ‖u − u_direct‖ / ‖u_direct‖ on the same model (compare_to_direct)
  double condition = nan;           // λ_max / λ_min of the last interface CG (mixed, feti)
};

json to_json(const CaseOutcome& o);
CaseOutcome outcome_from_json(const json& j);

CaseOutcome run_case(const SuiteCase& c);

}  // namespace rollsim::bench
