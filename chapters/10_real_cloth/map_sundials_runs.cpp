// Chapter 10's map: the SUNDIALS runs (CVODE's BDF and ARKODE's backward Euler with KLU on the definite Jacobian),
// guarded against a diverged state and stopped at a processor-time cap (see map_runs.hpp).
#include "map_run_common.hpp"

#include "program/interrupt.hpp"

#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>

using namespace cloth;
using namespace ch10::map_detail;

namespace ch10 {

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

}  // namespace ch10
