#include "Interrupt.h"

#include <unistd.h>

#include <csignal>

namespace rollsim::app {

namespace {
volatile std::sig_atomic_t signals = 0;  // how many arrived so far
volatile std::sig_atomic_t writing = 0;  // the phase of the scope installed last

extern "C" void on_interrupt(int sig) {
  signals = signals + 1;
  static const char analysis[] =
      "\nrollsim: interrupted: stopping after the current iteration and writing what the run completed "
      "(again to stop at once)\n";
  static const char results[] =
      "\nrollsim: interrupted: finishing the file being written, then the summary (again to stop at once)\n";
  const char* msg = writing ? results : analysis;
  const size_t size = writing ? sizeof results : sizeof analysis;
  [[maybe_unused]] const auto n = write(STDERR_FILENO, msg, size - 1);  // async-signal-safe, unlike stdio
  std::signal(sig, SIG_DFL);                                            // the second one ends the process
}

/// The handler, unless the signal was ignored when rollsim started (a background job of a script: Ctrl-C there is
/// meant for the foreground only, as with every well-behaved program). Returns the previous disposition.
void (*catch_signal(int sig))(int) {
  void (*previous)(int) = std::signal(sig, SIG_IGN);
  if (previous != SIG_IGN) std::signal(sig, on_interrupt);
  return previous;
}
}  // namespace

InterruptScope::InterruptScope(Phase phase)
    : signals_before_((writing = phase == Phase::writing, signals)),
      previous_int_(catch_signal(SIGINT)),
      previous_term_(catch_signal(SIGTERM)) {}

InterruptScope::~InterruptScope() {
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
}

bool InterruptScope::requested() const { return signals > signals_before_; }

}  // namespace rollsim::app
