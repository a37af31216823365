// The runs of Chapter 10's map (see map_runs.hpp).
#include "map_runs.hpp"

#include "peer_systems.hpp"
#include "plain_xpbd.hpp"

#include "analysis/reference_trajectory.hpp"
#include "integrators/configuration.hpp"
#include "program/interrupt.hpp"
#include "program/method_flags.hpp"
#include "program/timing.hpp"

#include <arkode/arkode_arkstep.h>
#include <boost/numeric/odeint.hpp>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>

#include <cmath>
#include <functional>
#include <memory>

using namespace cloth;

namespace ch10 {

namespace {

constexpr double frame_interval = 1.0 / 60;

/// Runs `body` (which fills a MapRun) and times it; a run shorter than 0.2 s is repeated twice and the fastest
/// time kept (on a shared machine the fastest run is the least disturbed).
MapRun timed(const std::function<MapRun()>& body) {
  double start = thread_cpu_seconds();
  MapRun run = body();
  run.seconds = thread_cpu_seconds() - start;
  for (int k = 0; k < 2 && run.ok && run.seconds < 0.2; ++k) {
    start = thread_cpu_seconds();
    body();
    run.seconds = std::min(run.seconds, thread_cpu_seconds() - start);
  }
  return run;
}

/// How many frames of `interval` fit in T.
long long frame_count(double interval, double T) { return std::llround(T / interval); }

std::unique_ptr<OdeSystem> system_for(const Scene& scene, Forces forces) {
  if (forces == Forces::plain) return std::make_unique<PlainSystem>(scene.params(), true);
  return std::make_unique<CoreSystem>(scene, true);
}

Frame frame_of(const OdeSystem& system, const std::vector<double>& y, double t) { return {t, system.positions(y)}; }

}  // namespace

MapRun book_run(const Scene& scene, const std::string& name, double h, double T) {
  Configuration c = parse_configuration(name);
  NewtonSettings& newton = c.settings.newton;
  newton.treatment = c.jacobian ? *c.jacobian : default_treatment(newton.solver, false);
  newton.tolerance = 1e-6;  // a velocity change below 1e-6 h in position: far under every level of the map
  newton.cg_tolerance = 1e-8;
  return timed([&] {
    ForceField field(scene);
    auto stepper = make_stepper(c.method, field, c.settings);
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

namespace {

// A SUNDIALS integration's resources, freed in reverse order whatever happens.
struct SundialsSetup {
  SUNContext context = nullptr;
  std::vector<double> y0;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver klu = nullptr;
  explicit SundialsSetup(OdeSystem& system) : y0(system.initial_state()) {
    check(SUNContext_Create(nullptr, &context), "SUNContext_Create");
    y = N_VMake_Serial(system.size(), y0.data(), context);
    A = SUNSparseMatrix(system.size(), system.size(), system.nonzeros(), CSC_MAT, context);
    klu = SUNLinSol_KLU(y, A, context);
  }
  ~SundialsSetup() {
    SUNLinSolFree(klu);
    SUNMatDestroy(A);
    N_VDestroy(y);
    SUNContext_Free(&context);
  }
  SundialsSetup(const SundialsSetup&) = delete;
  SundialsSetup& operator=(const SundialsSetup&) = delete;
};

// [escape_guard]
std::string format_cap_note(double cap, long steps, double t) {
  return "stopped at the run cap of " + format_number(cap, 3) + " s of CPU at step " + std::to_string(steps + 1) +
         " after t = " + format_number(t, 3) + " s";
}

/// A state with a coordinate beyond 1000 m (a position of a 1 m cloth, or a velocity) has diverged: CVODE at
/// tolerance 0.1 on the stiff curtain otherwise follows such a state for minutes, to 1e7 m. The right-hand side
/// then returns SUNDIALS' recoverable error (a Newton iterate far out is retried with a smaller step, as the
/// library does for any recoverable failure); a run that ends on it is reported as diverged.
constexpr double escape_radius = 1e3;
thread_local bool escaped = false;
/// The thread CPU time at which the running SUNDIALS integration is stopped (set_sundials_run_cap).
thread_local double cpu_deadline = INFINITY;
thread_local double run_cap = INFINITY;
thread_local bool capped = false;

/// Whether the run ended on the guard's refusals (the flag values are shared by CVODE and ARKODE).
bool ended_by_escape(int flag) {
  return escaped && (flag == CV_RHSFUNC_FAIL || flag == CV_FIRST_RHSFUNC_ERR || flag == CV_REPTD_RHSFUNC_ERR ||
                     flag == CV_UNREC_RHSFUNC_ERR);
}

int guarded_rhs(realtype t, N_Vector y, N_Vector ydot, void* data) {
  if (thread_cpu_seconds() > cpu_deadline) {
    capped = true;
    return -1;  // unrecoverable: the integration ends here
  }
  const Eigen::Map<const Eigen::VectorXd> state(N_VGetArrayPointer(y), N_VGetLength(y));
  if (!(state.cwiseAbs().maxCoeff() < escape_radius)) {
    escaped = true;
    return 1;
  }
  return rhs_callback(t, y, ydot, data);
}
// [escape_guard]

/// Arms the guard for one SUNDIALS integration: no escape seen, the CPU deadline run_cap from now.
void arm_guard() {
  escaped = capped = false;
  cpu_deadline = thread_cpu_seconds() + run_cap;
}

/// The note of a SUNDIALS run that ended with `flag` after `steps` steps at t.
std::string sundials_note(int flag, bool cvode, long steps, double t) {
  if (capped) return format_cap_note(run_cap, steps, t);
  return failure_note(sundials_end(flag, cvode, !ended_by_escape(flag)), steps, t);
}

}  // namespace

void set_sundials_run_cap(double seconds) { run_cap = seconds; }

MapRun cvode_run(const Scene& scene, Forces forces, double tol, int max_order, double T) {
  return timed([&] {
    auto system = system_for(scene, forces);
    SundialsSetup s(*system);
    MapRun run;
    void* mem = CVodeCreate(CV_BDF, s.context);
    check(CVodeSetErrFile(mem, nullptr), "CVodeSetErrFile");
    arm_guard();
    check(CVodeInit(mem, guarded_rhs, 0.0, s.y), "CVodeInit");
    check(CVodeSStolerances(mem, tol, tol), "CVodeSStolerances");
    check(CVodeSetUserData(mem, system.get()), "CVodeSetUserData");
    check(CVodeSetLinearSolver(mem, s.klu, s.A), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(mem, jacobian_callback), "CVodeSetJacFn");
    check(CVodeSetMaxOrd(mem, max_order), "CVodeSetMaxOrd");
    check(CVodeSetMaxNumSteps(mem, 10000000), "CVodeSetMaxNumSteps");
    run.frames.push_back(frame_of(*system, s.y0, 0));
    realtype t = 0;
    for (long long frame = 1; frame <= frame_count(frame_interval, T); ++frame) {
      const double target = static_cast<double>(frame) * frame_interval;
      check(CVodeSetStopTime(mem, target), "CVodeSetStopTime");
      const int flag = CVode(mem, target, s.y, &t, CV_NORMAL);
      long steps = 0;
      CVodeGetNumSteps(mem, &steps);
      run.steps = steps;
      if (flag < 0) {
        run.ok = false;
        run.note = sundials_note(flag, true, steps, t);
        break;
      }
      run.frames.push_back(frame_of(*system, s.y0, target));
    }
    CVodeFree(&mem);
    throw_if_interrupted();
    return run;
  });
}

MapRun arkode_run(const Scene& scene, Forces forces, double h, double T) {
  return timed([&] {
    auto system = system_for(scene, forces);
    SundialsSetup s(*system);
    MapRun run;
    arm_guard();
    void* mem = ARKStepCreate(nullptr, guarded_rhs, 0.0, s.y, s.context);
    check(ARKStepSetErrFile(mem, nullptr), "ARKStepSetErrFile");
    check(ARKStepSetUserData(mem, system.get()), "ARKStepSetUserData");
    check(ARKStepSetLinearSolver(mem, s.klu, s.A), "ARKStepSetLinearSolver");
    check(ARKStepSetJacFn(mem, jacobian_callback), "ARKStepSetJacFn");
    realtype c[] = {1}, a[] = {1}, b[] = {1};
    ARKodeButcherTable euler = ARKodeButcherTable_Create(1, 1, 0, c, a, b, nullptr);
    check(ARKStepSetTables(mem, 1, 0, euler, nullptr), "ARKStepSetTables");
    check(ARKStepSetFixedStep(mem, h), "ARKStepSetFixedStep");
    check(ARKStepSetJacEvalFrequency(mem, 1), "ARKStepSetJacEvalFrequency");
    check(ARKStepSetLSetupFrequency(mem, 1), "ARKStepSetLSetupFrequency");
    check(ARKStepSetMaxNonlinIters(mem, 20), "ARKStepSetMaxNonlinIters");
    check(ARKStepSetMaxNumSteps(mem, 10000000), "ARKStepSetMaxNumSteps");
    const double interval = std::max(h, frame_interval);
    run.frames.push_back(frame_of(*system, s.y0, 0));
    realtype t = 0;
    for (long long frame = 1; frame <= frame_count(interval, T); ++frame) {
      const double target = static_cast<double>(frame) * interval;
      const int flag = arkode_fixed_steps_to(mem, target, h, s.y, t);  // each step's own value (program/sundials.hpp)
      long steps = 0;
      ARKStepGetNumSteps(mem, &steps);
      run.steps = steps;
      if (flag < 0) {
        run.ok = false;
        run.note = sundials_note(flag, false, steps, t);
        break;
      }
      run.frames.push_back(frame_of(*system, s.y0, target));
    }
    ARKStepFree(&mem);
    ARKodeButcherTable_Free(euler);
    throw_if_interrupted();
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
