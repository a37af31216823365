// One SUNDIALS run of the cloth (Hindmarsh et al. 2005; Gardner et al. 2022): CVODE's variable-order BDF or
// ARKODE's diagonally implicit methods, each Newton system solved by KLU (Davis & Palamadai Natarajan 2010) on the
// analytic sparse Jacobian of the model, timed by the thread's processor time.
#include "benchmark.hpp"
#include "cloth_system.hpp"

#include "program/timing.hpp"

#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>
#include <sunlinsol/sunlinsol_klu.h>

#include <algorithm>
#include <stdexcept>

using namespace cloth;

namespace ch09 {
namespace {

void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string("SUNDIALS ") + call + " failed with flag " + std::to_string(flag));
}

// SUNDIALS' constructors return NULL when memory runs out: a failed allocation, never a null pointer used.
template <class Pointer>
Pointer allocated(Pointer p) {
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

// The counters CVODE and ARKStep both report, read through their (same-shaped) getter functions.
struct Counters {
  int (*steps)(void*, long*);
  int (*convergence_failures)(void*, long*);
  int (*newton_iterations)(void*, long*);
  int (*setups)(void*, long*);
  int (*current_step)(void*, realtype*);
};

void read_counters(void* mem, const Counters& get, Outcome& out) {
  get.steps(mem, &out.steps);
  get.convergence_failures(mem, &out.convergence_failures);
  get.newton_iterations(mem, &out.newton_iterations);
  get.setups(mem, &out.setups);
  realtype h = 0;
  get.current_step(mem, &h);
  out.failed_t = out.t + h;
}

// [sundials_runs]
// CVODE BDF (orders 1 to max_order, variable step), KLU on the analytic Jacobian, to T; returns CVode's flag.
int integrate_cvode(ClothSystem& system, const SundialsSettings& s, N_Vector y, SUNMatrix A, SUNLinearSolver klu,
                    SUNContext context, Outcome& out) {
  void* mem = allocated(CVodeCreate(CV_BDF, context));
  check(CVodeSetErrFile(mem, nullptr), "CVodeSetErrFile");  // a failure is reported in run.txt's terms
  check(CVodeInit(mem, ClothSystem::rhs, 0.0, y), "CVodeInit");
  check(CVodeSStolerances(mem, s.rtol, s.atol), "CVodeSStolerances");
  check(CVodeSetUserData(mem, &system), "CVodeSetUserData");
  check(CVodeSetLinearSolver(mem, klu, A), "CVodeSetLinearSolver");
  check(CVodeSetJacFn(mem, ClothSystem::jacobian), "CVodeSetJacFn");
  check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
  if (s.max_order < 5) check(CVodeSetMaxOrd(mem, s.max_order), "CVodeSetMaxOrd");
  realtype t = 0;
  const int flag = CVode(mem, s.T, y, &t, CV_NORMAL);  // its own Nordsieck interpolant of order q gives y(T)
  out.t = t;
  read_counters(mem, {CVodeGetNumSteps, CVodeGetNumNonlinSolvConvFails, CVodeGetNumNonlinSolvIters,
                      CVodeGetNumLinSolvSetups, CVodeGetCurrentStep}, out);
  CVodeFree(&mem);
  return flag;
}

// ARKODE's table for a solver name: Kennedy & Carpenter's ESDIRK3(2)4L[2]SA and ESDIRK4(3)6L[2]SA (the book's
// esdirk32 and esdirk43, entry for entry), or ARKStep's default implicit table, ARK3(2)4L[2]SA's ESDIRK.
ARKODE_DIRKTableID arkode_table(const std::string& solver) {
  if (solver == "arkode-esdirk32") return ARKODE_ESDIRK324L2SA_4_2_3;
  if (solver == "arkode-esdirk43") return ARKODE_ESDIRK436L2SA_6_3_4;
  return ARKODE_ARK324L2SA_DIRK_4_2_3;
}

// ARKODE under its own step control with the solver's table, or the one-stage backward Euler table at the fixed
// step h; KLU on the analytic Jacobian, to T. Returns ARKStepEvolve's flag.
int integrate_arkode(ClothSystem& system, const SundialsSettings& s, N_Vector y, SUNMatrix A, SUNLinearSolver klu,
                     SUNContext context, Outcome& out) {
  void* mem = allocated(ARKStepCreate(nullptr, ClothSystem::rhs, 0.0, y, context));
  check(ARKStepSetErrFile(mem, nullptr), "ARKStepSetErrFile");
  check(ARKStepSStolerances(mem, s.rtol, s.atol), "ARKStepSStolerances");
  check(ARKStepSetUserData(mem, &system), "ARKStepSetUserData");
  check(ARKStepSetLinearSolver(mem, klu, A), "ARKStepSetLinearSolver");
  check(ARKStepSetJacFn(mem, ClothSystem::jacobian), "ARKStepSetJacFn");
  check(ARKStepSetMaxNumSteps(mem, 1000000), "ARKStepSetMaxNumSteps");
  realtype t = 0;
  int flag = 0;
  ARKodeButcherTable euler = nullptr;
  if (s.solver == "arkode-backward-euler") {
    // SUNDIALS 6.4 has no built-in backward Euler table: c = A = b = 1, no embedding, fixed steps.
    realtype c[] = {1}, a[] = {1}, b[] = {1};
    euler = allocated(ARKodeButcherTable_Create(1, 1, 0, c, a, b, nullptr));
    check(ARKStepSetTables(mem, 1, 0, euler, nullptr), "ARKStepSetTables");
    check(ARKStepSetFixedStep(mem, s.h), "ARKStepSetFixedStep");
    // A fixed step cannot shrink when Newton needs more than ARKODE's default 3 iterations, so it gets the
    // iteration limit ch09_implicit_runge_kutta has (20).
    check(ARKStepSetMaxNonlinIters(mem, 20), "ARKStepSetMaxNonlinIters");
    // One step at a time, the last one shortened to end on T: ARKODE's output at T is then its own step's
    // solution, not its interpolant (which halves the step's change: the difference measured in Chapter 9).
    flag = arkode_fixed_steps_to(mem, s.T, s.h, y, t);
  } else {
    check(ARKStepSetTableNum(mem, arkode_table(s.solver), ARKODE_ERK_NONE), "ARKStepSetTableNum");
    // T as a stop time, and one step per call: the last step ends on T, as the book's driver's does, and y is
    // then read as that step's own solution (ARKODE's current state), not as its interpolant evaluated at T.
    check(ARKStepSetStopTime(mem, s.T), "ARKStepSetStopTime");
    do flag = ARKStepEvolve(mem, s.T, y, &t, ARK_ONE_STEP);
    while (flag == ARK_SUCCESS && t < s.T);
    N_Vector state = nullptr;
    if (flag >= 0 && ARKStepGetCurrentState(mem, &state) == ARK_SUCCESS) N_VScale(1.0, state, y);
  }
  out.t = t;
  read_counters(mem, {ARKStepGetNumSteps, ARKStepGetNumNonlinSolvConvFails, ARKStepGetNumNonlinSolvIters,
                      ARKStepGetNumLinSolvSetups, ARKStepGetCurrentStep}, out);
  if (euler) out.failed_t = std::min(t + s.h, s.T);  // the fixed step that failed (ARKODE's current step has moved on)
  ARKStepFree(&mem);
  if (euler) ARKodeButcherTable_Free(euler);
  return flag;
}
// [sundials_runs]

}  // namespace

Outcome sundials_run(const SundialsSettings& settings, ForceField& field, Vector& x, Vector& v) {
  ClothSystem system(field, settings.treatment);
  SUNContext context = nullptr;
  check(SUNContext_Create(nullptr, &context), "SUNContext_Create");
  N_Vector y = N_VNew_Serial(2 * system.n, context);
  if (y == nullptr) SUNContext_Free(&context);
  allocated(y);
  Eigen::Map<Vector>(N_VGetArrayPointer(y), system.n) = field.scene().initial_positions();
  Eigen::Map<Vector>(N_VGetArrayPointer(y) + system.n, system.n) = field.scene().initial_velocities();
  const sunindextype N = 2 * system.n;
  SUNMatrix A = allocated(SUNSparseMatrix(N, N, system.nonzeros(), CSC_MAT, context));
  SUNLinearSolver klu = SUNLinSol_KLU(y, A, context);
  if (klu == nullptr) SUNMatDestroy(A);
  allocated(klu);
  Outcome out;
  const bool cvode = settings.solver == "cvode-bdf";
  const double start = thread_cpu_seconds();
  const int flag = cvode ? integrate_cvode(system, settings, y, A, klu, context, out)
                         : integrate_arkode(system, settings, y, A, klu, context, out);
  out.seconds = thread_cpu_seconds() - start;
  out.rhs_evaluations = system.rhs_evaluations;
  out.jacobian_evaluations = system.jacobian_evaluations;
  const bool finite = Eigen::Map<const Vector>(N_VGetArrayPointer(y), N).allFinite();
  out.end = sundials_end(flag, cvode, finite);
  out.ok = out.end.status == RunStatus::ok;
  SUNLinSolFree(klu);
  SUNMatDestroy(A);
  x = Eigen::Map<const Vector>(N_VGetArrayPointer(y), system.n);
  v = Eigen::Map<const Vector>(N_VGetArrayPointer(y) + system.n, system.n);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return out;
}

}  // namespace ch09
