#pragma once
// What the engine reports while it runs; front ends (CLI progress, GUI plots) implement it.
#include <string>

namespace rollsim {

class AnalysisObserver {
 public:
  virtual ~AnalysisObserver() = default;
  /// A named stage starts ("assemble", "factorize", "solve", "recover").
  virtual void on_stage(const std::string& /*stage*/) {}
  /// True asks the analysis to stop at the next safe point.
  virtual bool cancel_requested() const { return false; }
};

}  // namespace rollsim
