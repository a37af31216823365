// Stopping a long run from the keyboard (Ctrl-C, SIGINT) or from the system (SIGTERM) without losing what it
// computed: the first signal only raises a flag, which the driver reads between two steps (RunSettings::stop),
// so the run ends at a step boundary and its outputs are written whole; the program then exits with 128 + the
// signal's number (130, 143), as a shell expects of a program a signal ended.
#pragma once

#include <atomic>
#include <string>

namespace cloth {

/// 0 while no stop was asked for, else the number of the signal that asked (SIGINT or SIGTERM).
const std::atomic<int>& interrupt_flag();

/// The signal that asked the program to stop, or 0.
int interrupt_signal();

/// Installs the handlers of SIGINT and SIGTERM (run_program does it for every chapter program). The first signal
/// sets interrupt_flag(); a second one is not waited for: it ends the program at once by the signal's default
/// action, which leaves at most the temporary `.partial` files of the outputs being written, never a partial file
/// under a final name.
void install_interrupt_handlers();

/// "SIGINT", "SIGTERM", or "signal N".
std::string signal_name(int signal);

/// Thrown by throw_if_interrupted(); run_program turns it into one line on stderr and exit status 128 + signal.
struct Interrupted {
  int signal;
};

/// Throws Interrupted when a stop was asked for: experiment programs call it between their runs.
void throw_if_interrupted();

}  // namespace cloth
