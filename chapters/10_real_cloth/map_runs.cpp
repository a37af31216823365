// The runs of Chapter 10's map (see map_runs.hpp).
#include "map_runs.hpp"

#include "map_run_common.hpp"
#include "plain_xpbd.hpp"
#include "study.hpp"

#include "analysis/reference_trajectory.hpp"
#include "program/interrupt.hpp"
#include "program/timing.hpp"

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <functional>
#include <memory>

using namespace cloth;

namespace ch10 {

using namespace map_detail;

MapRun book_run(const Scene& scene, const std::string& name, double h, double T) {
  return timed([&] {
    ForceField field(scene);
    auto stepper = make_method(name, field);  // the chapter's settings (study.cpp): Newton to 1e-6, at most 1000
    MapRun run;
    Vector x = scene.initial_positions(), v = scene.initial_velocities(), all(3 * scene.particle_count());
    const long long every = std::max(1LL, std::llround(frame_interval / h));
    run.steps = std::llround(T / h);
    scene.all_positions(x, all);
    run.frames.push_back({0, all});
    for (long long k = 1; k <= run.steps; ++k) {
      throw_if_interrupted();
      if (!stepper->step(h, x, v) || !x.allFinite() || x.cwiseAbs().maxCoeff() > 100) {
        run.ok = false;
        run.note = "step " + std::to_string(k) + " failed or diverged";
        break;
      }
      if (k % every == 0) {
        scene.all_positions(x, all);
        run.frames.push_back({static_cast<double>(k) * h, all});
      }
    }
    return run;
  });
}

MapRun book_dopri5_run(const Scene& scene, double tol, double T) {
  return timed([&] {
    ForceField field(scene);
    MapRun run;
    try {
      ReferenceTrajectory r = reference_trajectory(field, scene.initial_positions(), scene.initial_velocities(), T,
                                                   static_cast<int>(frame_count(frame_interval, T)), tol,
                                                   &interrupt_flag());
      throw_if_interrupted();
      run.steps = r.steps;
      run.frames = std::move(r.frames);
    } catch (const std::runtime_error& failed) {  // the pair's step fell below its floor, or the state diverged
      throw_if_interrupted();
      run.ok = false;
      run.note = failed.what();
    }
    return run;
  });
}

MapRun odeint_rk4_run(const Scene& scene, Forces forces, double h, double T) {
  return timed([&] {
    auto system = system_for(scene, forces);
    MapRun run;
    std::vector<double> y = system->initial_state();
    const auto f = [&](const std::vector<double>& state, std::vector<double>& dydt, double /*t*/) {
      throw_if_interrupted();  // odeint is C++: the exception passes through it
      system->rhs(state.data(), dydt.data());
    };
    boost::numeric::odeint::runge_kutta4<std::vector<double>> rk4;
    const long long per_frame = std::llround(frame_interval / h);
    run.frames.push_back(frame_of(*system, y, 0));
    for (long long frame = 1; frame <= frame_count(frame_interval, T); ++frame) {
      for (long long k = 0; k < per_frame; ++k, ++run.steps) rk4.do_step(f, y, static_cast<double>(run.steps) * h, h);
      run.frames.push_back(frame_of(*system, y, static_cast<double>(frame) * frame_interval));
    }
    return run;
  });
}

MapRun odeint_dopri5_run(const Scene& scene, Forces forces, double tol, double T) {
  namespace odeint = boost::numeric::odeint;
  return timed([&] {
    auto system = system_for(scene, forces);
    MapRun run;
    std::vector<double> y = system->initial_state(), times;
    for (long long frame = 0; frame <= frame_count(frame_interval, T); ++frame)
      times.push_back(static_cast<double>(frame) * frame_interval);
    const auto f = [&](const std::vector<double>& state, std::vector<double>& dydt, double /*t*/) {
      throw_if_interrupted();
      system->rhs(state.data(), dydt.data());
    };
    const auto observe = [&](const std::vector<double>& state, double t) { run.frames.push_back(frame_of(*system, state, t)); };
    // The documented way to output at given times: the dense-output stepper with integrate_times.
    auto stepper = odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<std::vector<double>>());
    run.steps = static_cast<long long>(odeint::integrate_times(stepper, f, y, times.begin(), times.end(), 1e-5, observe));
    return run;
  });
}


MapRun plain_xpbd_run(const Scene& scene, int substeps, double T) {
  const SceneParams& p = scene.params();
  return timed([&] {
    PlainXpbd xpbd(p.grid.M, p.grid.N, p.grid.d, p.stiffness, p.damping, p.mass, p.gravity, p.pins == PinSet::edge,
                   p.initial_swing);
    MapRun run;
    const auto positions = [&] { return Eigen::Map<const Vector>(xpbd.positions().data(), 3 * scene.particle_count()); };
    run.frames.push_back({0, positions()});
    for (long long frame = 1; frame <= frame_count(frame_interval, T); ++frame) {
      throw_if_interrupted();
      xpbd.step(frame_interval, substeps, 1);
      run.steps += substeps;
      run.frames.push_back({static_cast<double>(frame) * frame_interval, positions()});
    }
    return run;
  });
}

}  // namespace ch10
