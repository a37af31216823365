// The run's output files and its summary line, for every single-run chapter program.
#include "program/run_outputs.hpp"

#include "base/format_number.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/output_spec.hpp"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>

namespace cloth {

namespace {

// The signal a run stopped for: the value its stop flag holds (SIGINT if a test raised it with another value).
int stop_signal(const RunSettings& settings) {
  return settings.stop != nullptr ? settings.stop->load() : 0;
}

}  // namespace

void append_status(KeyValues& kv, const RunResult& result, int signal) {
  const auto num = [](double x) { return format_number(x, 10); };
  if (result.status == RunStatus::interrupted || (result.status == RunStatus::ok && signal != 0)) {
    kv.emplace_back("status", "interrupted");
    kv.emplace_back("signal", signal_name(signal != 0 ? signal : SIGINT));
    kv.emplace_back("reason", result.status == RunStatus::interrupted
                                  ? "stopped by the signal after step " + std::to_string(result.steps) + ", t = " +
                                        format_number(result.t) + " s"
                                  : "the signal came after the last step, while the outputs were written; every "
                                    "output file is whole");
  } else {
    kv.emplace_back("status", run_status_name(result.status));
    if (result.status == RunStatus::step_failed) kv.emplace_back("failure", step_failure_name(result.failure));
    if (result.status != RunStatus::ok) {
      kv.emplace_back("failed_step", std::to_string(result.failed_step));
      kv.emplace_back("failed_t", num(result.failed_t));
      kv.emplace_back("reason", result.reason);
    }
  }
}

std::vector<std::string> run_output_names() { return output_names(run_output_specs()); }

void write_outputs(const RunResult& result, const Stepper& stepper, const RunSettings& settings,
                   const KeyValues& extra) {
  const Scene& scene = stepper.field().scene();
  const std::string dir = settings.out_dir + "/";
  write_final(dir + "final.dat", scene, result.x, result.v);
  write_energy(dir + "energy.dat", result.energy);
  write_frames(dir + "frames.dat", scene.grid(), result.frames);
  const auto& p = scene.params();
  const auto num = [](double x) { return format_number(x, 10); };
  KeyValues kv = {
      {"method", stepper.name()},
      {"grid", std::to_string(p.grid.M) + "x" + std::to_string(p.grid.N)},
      {"spacing", num(p.grid.d)},
      {"mass", num(p.mass)},
      {"K", num(p.stiffness)},
      {"damping", num(p.damping)},
      {"damping_model", damping_model_name(p.damping_model)},
      {"pins", pin_set_name(p.pins)},
      {"v0", num(p.initial_velocity_z)},
      {"dt", num(settings.dt)},
      {"t_end", num(settings.t_end)},
      // What frames.dat holds after t = 0: for a fixed step at most one frame per step (frame_count), for an
      // adaptive run every frame asked for (interpolated), for a run that stopped early the frames up to then.
      {"frames", std::to_string(result.frames.empty() ? 0 : result.frames.size() - 1)},
      {"steps", std::to_string(result.steps)},
      {"t_reached", num(result.t)},
      {"wall_seconds", num(result.wall_seconds)},
      {"rhs_evaluations", std::to_string(result.counters.rhs_evaluations)},
      {"newton_iterations", std::to_string(result.counters.newton_iterations)},
      {"newton_iterations_per_step", num(result.newton_iterations_per_step())},
      {"jacobian_assemblies", std::to_string(result.counters.jacobian_assemblies)},
      {"factorizations", std::to_string(result.counters.factorizations)},
      {"cg_iterations", std::to_string(result.counters.cg_iterations)},
  };
  // The flexion springs' own stiffness only when one was given, so that every other run.txt stays as it was.
  if (p.flexion_stiffness) kv.insert(kv.begin() + 5, {"K_flexion", num(*p.flexion_stiffness)});
  // The Newton iterations that took the definite matrix instead of a singular or non-descending exact one, only
  // when there were any.
  if (result.counters.definite_fallbacks > 0) {
    const auto cg = std::find_if(kv.begin(), kv.end(), [](const auto& entry) { return entry.first == "cg_iterations"; });
    kv.insert(cg + 1, {"definite_fallbacks", std::to_string(result.counters.definite_fallbacks)});
  }
  // Likewise the initial swing, only when the run starts turning.
  if (p.initial_swing != 0) {
    const auto v0 = std::find_if(kv.begin(), kv.end(), [](const auto& entry) { return entry.first == "v0"; });
    kv.insert(v0 + 1, {"swing", num(p.initial_swing)});
  }
  kv.insert(kv.end(), extra.begin(), extra.end());
  append_status(kv, result, stop_signal(settings));
  write_key_values(dir + "run.txt", kv);
}

int report(const RunResult& result, const Stepper& stepper, const std::string& program) {
  if (result.status != RunStatus::ok) return report_stop(result, stepper.name(), program);
  std::printf("%s: %s, %lld steps to t = %g s in %.3f s, %lld force evaluations\n", program.c_str(),
              stepper.name().c_str(), result.steps, result.t, result.wall_seconds, result.counters.rhs_evaluations);
  return 0;
}

int report_stop(const RunResult& result, const std::string& method, const std::string& program) {
  switch (result.status) {
    case RunStatus::ok:
      return 0;
    case RunStatus::diverged:
    case RunStatus::step_failed:
      std::cerr << program << ": " << method << " " << result.message << "\n";
      return 3;
    case RunStatus::interrupted: {
      const int signal = interrupt_signal() != 0 ? interrupt_signal() : SIGINT;
      std::cerr << program << ": " << method << " interrupted by " << signal_name(signal) << " after step "
                << result.steps << ", t = " << format_number(result.t) << " s; the outputs up to then are kept\n";
      return 128 + signal;
    }
  }
  return 1;
}

int finish_run(const RunResult& result, const Stepper& stepper, const RunSettings& settings,
               const std::string& program, const KeyValues& extra) {
  write_outputs(result, stepper, settings, extra);
  if (frame_count(settings) < settings.frames)
    std::printf("%s: frames.dat holds %d frames after t = 0, one per step: the run has %lld steps, fewer than "
                "--frames %d\n", program.c_str(), frame_count(settings), step_count(settings), settings.frames);
  return report(result, stepper, program);
}

}  // namespace cloth
