#pragma once
// Ctrl-C (SIGINT) or SIGTERM during `rollsim run`: the analysis is cancelled between two iterations, as the
// window's Cancel, and the run writes what it completed (summary.json, convergence.csv, rolling.csv) with status
// `cancelled` (exit 5). A second signal stops the process at once.

namespace rollsim::app {

/// Installs the handlers for its lifetime and restores the previous ones after.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
  /// True once SIGINT or SIGTERM arrived.
  static bool requested();

 private:
  void (*previous_int_)(int);
  void (*previous_term_)(int);
};

}  // namespace rollsim::app
