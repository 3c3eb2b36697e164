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

InterruptScope::InterruptScope()
    : previous_int_(std::signal(SIGINT, on_interrupt)), previous_term_(std::signal(SIGTERM, on_interrupt)) {}

InterruptScope::~InterruptScope() {
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
}

bool InterruptScope::requested() { return interrupted != 0; }

}  // namespace rollsim::app
