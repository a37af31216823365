// Chapter 10's peer programs (peer_programs.hpp): Boost.Odeint and SUNDIALS driven as their documentation shows,
// each on an OdeSystem from rest to T.
#include "peer_programs.hpp"

#include "program/interrupt.hpp"
#include "program/sundials.hpp"

#include <arkode/arkode_arkstep.h>
#include <boost/numeric/odeint.hpp>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

using namespace cloth;

namespace ch10 {

// [odeint_peers]
// Boost.Odeint: classical RK4 at a fixed step, or Dormand-Prince 5(4) with odeint's step-size controller
// (absolute and relative tolerance tol) from a first step of 1e-5 s.
Outcome odeint_rk4(OdeSystem& system, double T, long long steps) {
  Outcome out{true, "", steps, system.initial_state()};
  const auto f = [&](const std::vector<double>& y, std::vector<double>& dydt, double /*t*/) {
    throw_if_interrupted();  // odeint is C++: the exception passes through it
    system.rhs(y.data(), dydt.data());
  };
  boost::numeric::odeint::runge_kutta4<std::vector<double>> rk4;
  const double h = T / static_cast<double>(steps);
  for (long long k = 0; k < steps; ++k) rk4.do_step(f, out.y, static_cast<double>(k) * h, h);
  return out;
}

Outcome odeint_dopri5(OdeSystem& system, double T, double tol) {
  namespace odeint = boost::numeric::odeint;
  Outcome out{true, "", 0, system.initial_state()};
  const auto f = [&](const std::vector<double>& y, std::vector<double>& dydt, double /*t*/) {
    throw_if_interrupted();
    system.rhs(y.data(), dydt.data());
  };
  auto stepper = odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<std::vector<double>>());
  out.steps = static_cast<long long>(odeint::integrate_adaptive(stepper, f, out.y, 0.0, T, 1e-5));
  return out;
}
// [odeint_peers]

// [sundials_peers]
// SUNDIALS: CVODE's variable-order, variable-step BDF with tolerances rtol = atol = tol, or ARKODE with the
// one-stage backward Euler table (c = A = b = 1; SUNDIALS 6.4 has none built in) at the fixed step T / steps.
// Both solve their Newton systems with KLU on the analytic Jacobian. ARKODE's backward Euler evaluates the
// Jacobian at the start of every step and runs either its Newton iteration on it, allowed 20 iterations (its
// default of 3 fails at frame steps, and a fixed step cannot shrink instead), or declared linearly implicit
// (ARKStepSetLinear): one Newton iteration, which is Baraff and Witkin's step.
Outcome sundials_run(OdeSystem& system, Sundials peer, double T, double tol, long long steps) {
  SUNContext context = nullptr;
  check(SUNContext_Create(nullptr, &context), "SUNContext_Create");
  Outcome out{true, "", 0, system.initial_state()};
  N_Vector y = N_VMake_Serial(system.size(), out.y.data(), context);
  SUNMatrix A = SUNSparseMatrix(system.size(), system.size(), system.nonzeros(), CSC_MAT, context);
  SUNLinearSolver klu = SUNLinSol_KLU(y, A, context);
  realtype t = 0;
  long steps_taken = 0;
  if (peer == Sundials::cvode_bdf) {
    void* mem = CVodeCreate(CV_BDF, context);
    check(CVodeSetErrFile(mem, nullptr), "CVodeSetErrFile");  // a failure is reported with the run's results
    check(CVodeInit(mem, rhs_callback, 0.0, y), "CVodeInit");
    check(CVodeSStolerances(mem, tol, tol), "CVodeSStolerances");
    check(CVodeSetUserData(mem, &system), "CVodeSetUserData");
    check(CVodeSetLinearSolver(mem, klu, A), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(mem, jacobian_callback), "CVodeSetJacFn");
    check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
    const int flag = CVode(mem, T, y, &t, CV_NORMAL);
    CVodeGetNumSteps(mem, &steps_taken);
    if (flag < 0) out = {false, failure_note(sundials_end(flag, true, true), steps_taken, t), 0, {}};
    CVodeFree(&mem);
  } else {
    void* mem = ARKStepCreate(nullptr, rhs_callback, 0.0, y, context);
    check(ARKStepSetErrFile(mem, nullptr), "ARKStepSetErrFile");
    check(ARKStepSetUserData(mem, &system), "ARKStepSetUserData");
    check(ARKStepSetLinearSolver(mem, klu, A), "ARKStepSetLinearSolver");
    check(ARKStepSetJacFn(mem, jacobian_callback), "ARKStepSetJacFn");
    realtype c[] = {1}, a[] = {1}, b[] = {1};
    ARKodeButcherTable euler = ARKodeButcherTable_Create(1, 1, 0, c, a, b, nullptr);
    check(ARKStepSetTables(mem, 1, 0, euler, nullptr), "ARKStepSetTables");
    check(ARKStepSetFixedStep(mem, T / static_cast<double>(steps)), "ARKStepSetFixedStep");
    // ARKODE keeps a Jacobian for up to 51 steps by default: at a frame step that is the whole run on the
    // Jacobian of the flat sheet, which has no stiffness across it. Both forms evaluate it at every step.
    check(ARKStepSetJacEvalFrequency(mem, 1), "ARKStepSetJacEvalFrequency");
    check(ARKStepSetLSetupFrequency(mem, 1), "ARKStepSetLSetupFrequency");
    if (peer == Sundials::arkode_linear)
      check(ARKStepSetLinear(mem, 1), "ARKStepSetLinear");
    else
      check(ARKStepSetMaxNonlinIters(mem, 20), "ARKStepSetMaxNonlinIters");
    check(ARKStepSetMaxNumSteps(mem, 1000000), "ARKStepSetMaxNumSteps");
    // Step by step to T: the last step's own value, not ARKODE's interpolant (program/sundials.hpp).
    const int flag = arkode_fixed_steps_to(mem, T, T / static_cast<double>(steps), y, t);
    ARKStepGetNumSteps(mem, &steps_taken);
    if (flag < 0) out = {false, failure_note(sundials_end(flag, false, true), steps_taken, t), 0, {}};
    ARKStepFree(&mem);
    ARKodeButcherTable_Free(euler);
  }
  out.steps = steps_taken;
  SUNLinSolFree(klu);
  SUNMatDestroy(A);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return out;
}
// [sundials_peers]

}  // namespace ch10
