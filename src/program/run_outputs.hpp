// What a finished run leaves behind: the output files of the model page (final.dat, energy.dat, frames.dat,
// run.txt) and the one-line summary with the exit status.
#pragma once

#include "integrators/simulate.hpp"

#include <string>
#include <utility>
#include <vector>

namespace cloth {

/// Writes final.dat, energy.dat, frames.dat and run.txt into settings.out_dir, with `extra` lines in run.txt.
void write_outputs(const RunResult& result, const Stepper& stepper, const RunSettings& settings,
                   const std::vector<std::pair<std::string, std::string>>& extra = {});

/// Prints a one-line summary, and for a failed run one line on stderr with the step and time; returns the exit
/// status of docs/model.md (0 finished, 3 diverged or failed).
int report(const RunResult& result, const Stepper& stepper, const std::string& program);

}  // namespace cloth
