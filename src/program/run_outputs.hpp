// What a finished run leaves behind: the output files of the model page (final.dat, energy.dat, frames.dat,
// run.txt), the one-line summary, and the exit status.
//
// run.txt is `key = value` lines: the scene (grid, spacing, mass, K, damping, damping_model, pins, v0), the run
// (method, dt, t_end, frames: the frames frames.dat holds after t = 0, steps, t_reached, wall_seconds) and its work counters (rhs_evaluations,
// newton_iterations, newton_iterations_per_step, jacobian_assemblies, factorizations, cg_iterations), then the
// chapter's own keys, and last how the run ended:
//   status = ok | diverged | step_failed | interrupted
//   failure = newton_not_converged       step_failed only: the StepFailureKind name (integrators/stepper.hpp):
//                                        newton_not_converged, factorization_singular, cg_not_converged,
//                                        refinement_failed, line_search_exhausted, step_size_too_small
//   failed_step = 12                     diverged and step_failed: the step that could not be taken (1-based)
//   failed_t = 0.12                      the time that step was to reach [s]
//   signal = SIGINT                      interrupted only: SIGINT or SIGTERM
//   reason = ...                         every status but ok: what happened, in one line
// `steps` and `t_reached` always say where the outputs end: the last good state (for interrupted, the last step
// taken before the stop; a signal that came while the outputs were written, after the last step, still gives
// `interrupted`, with every file whole).
#pragma once

#include "integrators/simulate.hpp"

#include <string>
#include <utility>
#include <vector>

namespace cloth {

using KeyValues = std::vector<std::pair<std::string, std::string>>;

/// Writes final.dat, energy.dat, frames.dat and run.txt into settings.out_dir, with `extra` lines in run.txt
/// before its status lines. Throws OutputError when a file cannot be written.
void write_outputs(const RunResult& result, const Stepper& stepper, const RunSettings& settings,
                   const KeyValues& extra = {});

/// Appends run.txt's closing status block for `result` (the lines above, from `status` on); `signal` is the stop
/// request the run saw (0: none), which also marks a run that finished as the signal came as interrupted.
/// write_outputs closes run.txt with it; a program that writes its own run.txt (a benchmark's) does the same.
void append_status(KeyValues& kv, const RunResult& result, int signal);

/// The names write_outputs writes, for prepare_outputs.
std::vector<std::string> run_output_names();

/// Prints a one-line summary on stdout, or for a run that did not finish one line on stderr with its status,
/// step and time; returns the exit status of the model page: 0 finished, 3 diverged or a step failed,
/// 128 + signal (130, 143) interrupted.
int report(const RunResult& result, const Stepper& stepper, const std::string& program);

/// report's line and status for a run that did not finish (nothing for one that did: status 0), its method named
/// `method`: for a program whose run is not a Stepper's (a library's integrator).
int report_stop(const RunResult& result, const std::string& method, const std::string& program);

/// write_outputs, then report; also says on stdout when frames.dat holds fewer frames than `--frames` asked for
/// (at most one per step). The one call a single-run program makes after simulate.
int finish_run(const RunResult& result, const Stepper& stepper, const RunSettings& settings,
               const std::string& program, const KeyValues& extra = {});

}  // namespace cloth
