#include "Interrupt.h"

#include <unistd.h>

#include <csignal>

namespace rollsim::app {

namespace {
volatile std::sig_atomic_t interrupted = 0;

extern "C" void on_interrupt(int sig) {
  interrupted = 1;
  static const char msg[] =
      "\nrollsim: interrupted: stopping after the current iteration and writing what the run completed "
      "(again to stop at once)\n";
  [[maybe_unused]] const auto n = write(STDERR_FILENO, msg, sizeof msg - 1);  // async-signal-safe, unlike stdio
  std::signal(sig, SIG_DFL);                                                  // the second one ends the process
}
}  // namespace

namespace {
/// The handler, unless the signal was ignored when rollsim started (a background job of a script: Ctrl-C there is
/// meant for the foreground only, as with every well-behaved program). Returns the previous disposition.
void (*catch_signal(int sig))(int) {
  void (*previous)(int) = std::signal(sig, SIG_IGN);
  if (previous != SIG_IGN) std::signal(sig, on_interrupt);
  return previous;
}
}  // namespace

InterruptScope::InterruptScope() : previous_int_(catch_signal(SIGINT)), previous_term_(catch_signal(SIGTERM)) {}

InterruptScope::~InterruptScope() {
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
}

bool InterruptScope::requested() { return interrupted != 0; }

}  // namespace rollsim::app
