#pragma once
// What the engine reports while it runs; front ends (CLI progress, GUI plots) implement it.
// Calls come from the thread that runs the analysis: a GUI forwards them through queued signals.
#include <string>

namespace rollsim {

class AnalysisObserver {
 public:
  virtual ~AnalysisObserver() = default;
  /// A named stage starts ("assemble", "factorize", "solve", "recover").
  virtual void on_stage(const std::string& /*stage*/) {}
  /// One iteration of an iterative process: `kind` is "cg" (interface CG / projected CG of one
  /// linear solve), "active_set" (contact status loop) or "newton"; `residual` is relative (dimensionless).
  virtual void on_iteration(const std::string& /*kind*/, int /*iteration*/, double /*residual*/) {}
  /// Fraction of the whole analysis done, in [0, 1] (per increment once increments exist).
  virtual void on_progress(double /*fraction*/) {}
  /// True asks the analysis to stop at the next safe point.
  virtual bool cancel_requested() const { return false; }
};

}  // namespace rollsim
