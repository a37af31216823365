// A progress line for a long run, on stderr when it is a terminal: steps done, time spent and an estimate of the
// time left, so that a reader who asked for a long simulation sees it advance and can decide to stop it (Ctrl-C).
#pragma once

#include "integrators/simulate.hpp"

#include <string>

namespace cloth {

/// A ProgressCallback for RunSettings::progress. It draws nothing during the first two seconds (short runs stay
/// silent), then redraws one line at most four times a second, `label: step k of n (p %), t s spent, about r s
/// left`, and clears it when the run ends. When stderr is not a terminal (a log file, a pipe, a test) it returns
/// an empty callback, and the run is not even asked to call it.
ProgressCallback terminal_progress(const std::string& label);

}  // namespace cloth
