// The stepping loop of Chapter 11's studies.
#include "studies.hpp"

#include "program/output.hpp"
#include "program/timing.hpp"

#include <cmath>

using namespace cloth;

namespace ch11 {

BuiltScene build_scene(SceneKind kind, const ContactFlags& flags, const Grid* grid) {
  BuiltScene b;
  SceneParams& p = b.params;
  for (const auto& [flag, value] : scene_defaults(kind)) {
    const std::string f = flag, text = value;
    if (f == "--grid") {
      const auto x = text.find('x');
      p.grid.M = std::stoi(text.substr(0, x));
      p.grid.N = std::stoi(text.substr(x + 1));
    } else if (f == "--spacing") p.grid.d = std::stod(text);
    else if (f == "--mass") p.mass = std::stod(text);
    else if (f == "--K") p.stiffness = std::stod(text);
    else if (f == "--damping") p.damping = std::stod(text);
  }
  p.pins = PinSet::none;
  p.initial_velocity_z = 0;
  if (grid) p.grid = *grid;
  b.model = place_scene(kind, flags, p, b.geometry);
  b.scene = std::make_unique<Scene>(p);
  b.field = std::make_unique<ForceField>(*b.scene);
  return b;
}

FoldStudyRun fold_study_run(const Study& study) {
  return {cloth::Grid{30, study.quick ? 100 : 200, 0.01}, study.quick ? 1.0 : 1.5, 5e-4};
}

SteppedRun step_run(Stepper& stepper, const BuiltScene& built, double h, double T, int frames,
                    const std::function<void(const Vector&)>& after_step) {
  SteppedRun run;
  run.x = built.scene->initial_positions();
  run.v = built.scene->initial_velocities();
  const auto steps = static_cast<long long>(std::llround(T / h));
  const long long stride = std::max(1LL, steps / frames);
  run.frames.push_back({0.0, run.x});
  const double m = built.params.mass;
  const double start = thread_cpu_seconds();
  for (long long k = 1; k <= steps; ++k) {
    if (!stepper.step(h, run.x, run.v)) {
      run.ok = false;
      run.failure = stepper.failure().reason;
      break;
    }
    run.steps = k;
    run.deepest = std::max(run.deepest, deepest_penetration(built.model, run.x));
    run.t.push_back(static_cast<double>(k) * h);
    run.kinetic.push_back(0.5 * m * run.v.squaredNorm());
    if (after_step) after_step(run.x);
    if (k % stride == 0) run.frames.push_back({static_cast<double>(k) * h, run.x});
  }
  run.seconds = thread_cpu_seconds() - start;
  return run;
}

void write_scene_frames(const Study& study, const std::string& scene, const BuiltScene& built,
                        const std::vector<Frame>& frames) {
  write_frames(study.dir + "/" + scene + "_frames.dat", built.params.grid, frames);
  write_key_values(study.dir + "/" + scene + "_geometry.txt", built.geometry);
}

}  // namespace ch11
