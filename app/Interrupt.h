#pragma once
// Ctrl-C (SIGINT) or SIGTERM during `rollsim run`: the analysis is cancelled between two iterations, as the
// window's Cancel, and the run writes what it completed (summary.json, convergence.csv, rolling.csv) with status
// `cancelled` (exit 5). While the results are written (a scope of its own, Phase::writing), a signal lets the file
// being written finish and ends the writing there: the folder holds complete files and a summary.json saying
// `cancelled` and what is missing. A second signal stops the process at once (no file is ever left cut off under
// its final name: every write goes to a temporary first).

namespace rollsim::app {

/// Installs the handlers for its lifetime and restores the previous ones after.
class InterruptScope {
 public:
  enum class Phase { analysis, writing };  // what the handler's message says the signal stops
  explicit InterruptScope(Phase phase = Phase::analysis);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
  /// True once SIGINT or SIGTERM arrived within this scope.
  bool requested() const;

 private:
  int signals_before_;
  void (*previous_int_)(int);
  void (*previous_term_)(int);
};

}  // namespace rollsim::app
