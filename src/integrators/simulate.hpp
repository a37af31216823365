// The one driver every chapter uses: run a scene with any Stepper at fixed h to t_end, record energy and frames,
// count the work, time it, and stop cleanly when the state diverges or a step fails.
#pragma once

#include "integrators/stepper.hpp"

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace cloth {

/// Called by the driver after each step with the steps done and the steps asked for, and once more when the run
/// ends (finished = true), so that a progress display can clear its line.
using ProgressCallback = std::function<void(long long done, long long total, bool finished)>;

/// Time stepping and output settings of a run.
struct RunSettings {
  double dt = 0.01;      ///< h [s]
  double t_end = 2.0;    ///< T [s]
  int frames = 20;       ///< frames.dat holds the cloth at t = k T / frames, k = 0..frames (at most one per step)
  std::string out_dir;   ///< where outputs go
  /// When set, the driver reads it once before each step and stops the run when it is not 0 (the program layer
  /// points it at the flag its SIGINT and SIGTERM handler raises). An atomic load is all it costs, so the
  /// integrators know nothing of signals.
  const std::atomic<int>* stop = nullptr;
  ProgressCallback progress;  ///< when set, told of the run's progress after every step
};

/// One line of energy.dat.
struct EnergySample {
  double t;
  Energy energy;
};

/// The cloth at one instant: every particle's position in grid order (3 per particle).
struct Frame {
  double t;
  Vector positions;
};

/// How a run ended: the statuses of run.txt (the model page's table).
enum class RunStatus {
  ok,           ///< every step taken
  diverged,     ///< a step gave a non-finite state or one beyond divergence_radius
  step_failed,  ///< the method could not take a step (RunResult::failure says why)
  interrupted   ///< RunSettings::stop was raised: the run stopped between two steps
};

/// The contract's name of a status: "ok", "diverged", "step_failed", "interrupted".
const char* run_status_name(RunStatus status);

/// What a run produced. x, v are the last sane state (at time t); energy and frames stop there too.
struct RunResult {
  RunStatus status = RunStatus::ok;
  std::string message;      ///< "ok", or what went wrong with the step number and time, in one line
  StepFailureKind failure = StepFailureKind::none;  ///< step_failed: the kind the stepper reported
  long long failed_step = 0;  ///< diverged, step_failed: the step that could not be taken (1-based), else 0
  double failed_t = 0;        ///< the time that step was to reach
  std::string reason;         ///< diverged, step_failed: what was wrong, without step and time
  long long steps = 0;      ///< steps completed
  double t = 0;             ///< time reached
  double wall_seconds = 0;  ///< time spent stepping (recording included)
  StepCounters counters;
  Vector x, v;
  std::vector<EnergySample> energy;  ///< one sample per step, t = 0 included
  std::vector<Frame> frames;         ///< the cloth at t = k T / frames

  /// Newton iterations per completed step (0 without steps, and for an explicit method).
  [[nodiscard]] double newton_iterations_per_step() const {
    return steps > 0 ? static_cast<double>(counters.newton_iterations) / static_cast<double>(steps) : 0.0;
  }
};

/// A state is declared diverged when a coordinate is not finite or a particle is farther from the origin than
///   R = 10 (L + |v0| T + g T^2 / 2) + 1 m,
/// L the cloth's rest diagonal: ten times farther than a particle launched at v0 and falling freely for T could be.
double divergence_radius(const Scene& scene, double t_end);

/// Records why a run stopped at `step` (1-based), on its way to time t (status, failure kind, step, time,
/// reason) and says it in one line in result.message: the drivers' shared wording (simulate, adaptive_simulate).
void stop_run(RunResult& result, RunStatus status, StepFailureKind kind, long long step, double t,
              std::string reason);

/// Checks (x, v) against divergence_radius; returns an empty string when sane, else what is wrong.
std::string divergence_reason(const Vector& x, const Vector& v, double radius);

/// The number of steps a run of settings takes: ceil(T / h), a last step shortened when T is not a multiple of h.
long long step_count(const RunSettings& settings);

/// The frames a recorded run keeps beyond t = 0: settings.frames, but never more than one per step.
int frame_count(const RunSettings& settings);

/// Runs the scene's initial state to settings.t_end with steps of settings.dt (the last one shortened if T is
/// not a multiple of h). Nothing is allocated inside the step loop: every buffer is sized before it starts.
RunResult simulate(Stepper& stepper, const RunSettings& settings, bool record = true);

}  // namespace cloth
