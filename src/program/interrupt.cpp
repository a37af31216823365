// The SIGINT and SIGTERM handler and its flag, for program/interrupt.hpp.
#include "program/interrupt.hpp"

#include <csignal>
#include <signal.h>

namespace cloth {

namespace {

// A lock-free atomic is what a signal handler may touch (C++17 [support.signal]); int's is on every platform the
// book builds on, and the static_assert keeps it so.
std::atomic<int> requested_stop{0};
static_assert(std::atomic<int>::is_always_lock_free, "the stop flag must be lock-free to be set by a signal handler");

extern "C" void on_stop_signal(int signal) {
  int none = 0;
  if (requested_stop.compare_exchange_strong(none, signal)) return;  // the first: the run stops at its next step
  // The second: the signal's default action, now. sigaction and raise are async-signal-safe; the signal stays
  // blocked until this handler returns, and is then delivered with its default action.
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  sigaction(signal, &default_action, nullptr);
  raise(signal);
}

}  // namespace

const std::atomic<int>& interrupt_flag() { return requested_stop; }

int interrupt_signal() { return requested_stop.load(); }

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a write interrupted by the signal resumes instead of failing with EINTR
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

void throw_if_interrupted() {
  if (const int signal = interrupt_signal(); signal != 0) throw Interrupted{signal};
}

}  // namespace cloth
