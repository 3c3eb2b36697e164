#pragma once
// What the engine reports while it runs; front ends (CLI progress, GUI plots) implement it. One typed hook per
// event, for today's linear analysis and for the incremental Newton driver to come. An analysis reports, in order:
//
//   on_stage("assemble")
//   on_increment_begin(i, n)                 load increment i of n (analysis.increments; 1 of 1 by default)
//     on_tangents(i, k, choices)             Newton driver only: which groups iteration k refactors, and why
//     on_newton_iteration(i, k, residual)    Newton driver only, after each iteration
//     on_factorization(group)                each numeric factorization, named by group
//     on_cg_iteration(solve, k, residual)    each (projected) CG iteration of linear solve `solve`
//     on_solve_end(solve, cg_iterations)     a linear solve is complete (0 CG iterations for direct strategies)
//     on_active_set_iteration(it, changed)   frictionless contact: statuses changed after the increment's solve `it`
//     on_cutback(i, cause)                   Newton driver only: the attempt at increment i failed; it is retried
//                                            from the last converged state with half the step
//   on_increment_end(i, n), on_progress(i / n)  … then increment i + 1 from on_increment_begin
//   on_stage("recover")
//
// Linear solves are numbered 1, 2, ... over the whole run (active-set iterations, later Newton iterations of every
// increment). Calls come from the thread that runs the analysis, one at a time (factorizations on worker threads
// are reported after they joined): a GUI forwards them through queued signals.
#include <string>
#include <vector>

#include "base/Measures.h"

namespace rollsim {

/// What a Newton iteration does with one group's tangent: re-assembles and refactors it, or keeps last iteration's
/// factor, and why: "first" (the run's first iteration), "cut-back", `always` (the policy), "share 0.43 > 0.01" (its
/// residual's share of the total against the selective threshold), "constant" (an elastic small-strain group's one
/// factor).
struct TangentChoice {
  std::string group;
  bool refactored = true;
  std::string why;
};

/// The choices in one line, as convergence.csv and the window's log show them:
/// "slab refactored (share 0.43 > 0.01); roll kept (share 0.0031 ≤ 0.01)".
inline std::string describe(const std::vector<TangentChoice>& choices) {
  std::string s;
  for (const TangentChoice& c : choices)
    s += (s.empty() ? "" : "; ") + c.group + (c.refactored ? " refactored (" : " kept (") + c.why + ")";
  return s;
}

class AnalysisObserver {
 public:
  virtual ~AnalysisObserver() = default;
  /// A named stage starts ("assemble", "solve", "recover").
  virtual void on_stage(const std::string& /*stage*/) {}
  /// Load increment `increment` (1-based) of `count` starts / is complete (not called for an increment a cancel
  /// interrupted).
  virtual void on_increment_begin(int /*increment*/, int /*count*/) {}
  virtual void on_increment_end(int /*increment*/, int /*count*/) {}
  /// Newton iteration `iteration` (1-based) of increment `increment`: ‖r_k‖ / ‖r_0‖ of the out-of-balance force
  /// (dimensionless). Reserved for the nonlinear driver; the GUI plots it as the "newton" series.
  virtual void on_newton_iteration(int /*increment*/, int /*iteration*/, double /*residual*/) {}
  /// Before the linear solve of Newton iteration `iteration` (1-based) of increment `increment`: every group's choice.
  virtual void on_tangents(int /*increment*/, int /*iteration*/, const std::vector<TangentChoice>& /*choices*/) {}
  /// Iteration `iteration` (1-based) of the interface (projected) CG of linear solve `solve`: ‖P r_k‖ / ‖P r_0‖
  /// (paper eqs. (7)-(8), dimensionless).
  virtual void on_cg_iteration(int /*solve*/, int /*iteration*/, double /*residual*/) {}
  /// Linear solve `solve` is complete after `cg_iterations` CG iterations (0: a direct strategy).
  virtual void on_solve_end(int /*solve*/, int /*cg_iterations*/) {}
  /// A numeric factorization of `group` (a body, or `body/<id>` subdomain; a global factorization reports every
  /// group it holds), as counted in summary.json's solver.factorizations.
  virtual void on_factorization(const std::string& /*group*/) {}
  /// Active-set iteration `iteration` (1-based within the increment; with one increment, its linear solve) changed
  /// `changed` contact statuses (0: settled).
  virtual void on_active_set_iteration(int /*iteration*/, int /*changed*/) {}
  /// The Newton driver's attempt at increment `increment` failed for `cause` (e.g. "no convergence in 25 iterations
  /// (residual ratio 0.003, tolerance 1e-08)"): it restores the last converged state and retries with half the step.
  /// Not called for the failure that ends the run (that one is the result's `diverged` status).
  virtual void on_cutback(int /*increment*/, const std::string& /*cause*/) {}
  /// A process measures each increment: the columns of its rows (their names, labels and units) and the chart that
  /// plots them as they come; said once, before the first increment.
  virtual void on_measures_begin(const MeasureTable& /*columns*/, const ChartRequest& /*chart*/) {}
  /// The process's row of an increment that is complete (not the last: its fields come with the results).
  virtual void on_measured(int /*increment*/, const MeasureRow& /*row*/) {}
  /// Fraction of the increments done, in [0, 1].
  virtual void on_progress(double /*fraction*/) {}
  /// True asks the analysis to stop at the next safe point: between CG iterations, before every linear solve
  /// (between active-set iterations) and before every increment. The results of a cancelled run are those of the
  /// last iterate (see Results::status).
  virtual bool cancel_requested() const { return false; }
};

}  // namespace rollsim
