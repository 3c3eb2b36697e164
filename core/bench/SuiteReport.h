#pragma once
// The judged cases written out: the CSV of every measurement, the time–error Pareto front per family, and the
// markdown tables of docs/BENCHMARKS-ACCURACY.md and docs/BENCHMARKS-STABILITY.md.
#include <string>
#include <vector>

#include "bench/Verdict.h"

namespace rollsim::bench {

/// results[i] is on its family's front: converged within any bound, with a finite error, not a reference, and no
/// other such case of the family is faster and as accurate, or as fast and more accurate (errors within 1 % tie).
std::vector<bool> pareto_front(const std::vector<CaseResult>& results);

/// One row per case: suite, family, variant, mode, level, cg_tolerance, status, verdict, wall_s, peak_rss_mb,
/// dofs, multipliers, subdomains, rigid_modes,
/// cg_iterations, factorizations, newton_iterations, active_set_iterations, quantity, value, reference, reference_kind,
/// error, solver_error, condition, bound, pareto, words.
std::string suite_csv(const std::vector<CaseResult>& results, const std::vector<bool>& pareto);

/// Per family: the Pareto front as a table (mode, mesh, tolerance, time, memory, iterations, error) and its plot
/// `image_prefix` + family + ".png".
std::string accuracy_markdown(const std::vector<CaseResult>& results, const std::vector<bool>& pareto,
                              const std::string& image_prefix);
/// The verdicts counted per family, then every case that is not ok, then every case.
std::string stability_markdown(const std::vector<CaseResult>& results);

}  // namespace rollsim::bench
