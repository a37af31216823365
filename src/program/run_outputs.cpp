// The run's output files and its summary line, for every single-run chapter program.
#include "program/run_outputs.hpp"

#include "program/output.hpp"

#include <cstdio>
#include <iostream>

namespace cloth {

void write_outputs(const RunResult& result, const Stepper& stepper, const RunSettings& settings,
                   const std::vector<std::pair<std::string, std::string>>& extra) {
  const Scene& scene = stepper.field().scene();
  const std::string dir = settings.out_dir + "/";
  write_final(dir + "final.dat", scene, result.x, result.v);
  write_energy(dir + "energy.dat", result.energy);
  write_frames(dir + "frames.dat", scene.grid(), result.frames);
  const auto& p = scene.params();
  const auto num = [](double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return std::string(buf);
  };
  std::vector<std::pair<std::string, std::string>> kv = {
      {"method", stepper.name()},
      {"grid", std::to_string(p.grid.M) + "x" + std::to_string(p.grid.N)},
      {"spacing", num(p.grid.d)},
      {"K", num(p.stiffness)},
      {"damping", num(p.damping)},
      {"damping_model", damping_model_name(p.damping_model)},
      {"pins", pin_set_name(p.pins)},
      {"v0", num(p.initial_velocity_z)},
      {"dt", num(settings.dt)},
      {"t_end", num(settings.t_end)},
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
  kv.insert(kv.end(), extra.begin(), extra.end());
  kv.emplace_back("status", result.status == RunStatus::ok ? "ok" : result.message);
  write_key_values(dir + "run.txt", kv);
}

int report(const RunResult& result, const Stepper& stepper, const std::string& program) {
  if (result.status == RunStatus::ok) {
    std::printf("%s: %s, %lld steps to t = %g s in %.3f s, %lld force evaluations\n", program.c_str(),
                stepper.name().c_str(), result.steps, result.t, result.wall_seconds, result.counters.rhs_evaluations);
    return 0;
  }
  std::cerr << program << ": " << stepper.name() << " " << result.message << "\n";
  return 3;
}

}  // namespace cloth
