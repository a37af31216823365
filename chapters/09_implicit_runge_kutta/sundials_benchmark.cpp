// Chapter 9's reference point: the same cloth integrated by SUNDIALS (Hindmarsh et al. 2005; Gardner et al. 2022),
// CVODE's variable-order BDF and ARKODE's diagonally implicit methods, each Newton system solved by KLU (Davis &
// Palamadai Natarajan 2010) on the analytic sparse Jacobian of the model. The chapter compares its own methods
// with these runs.
#include "program/command_line.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "analysis/trajectory_measures.hpp"
#include "integrators/configuration.hpp"
#include "integrators/implicit_step_control.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"
#include "program/run_outputs.hpp"
#include "program/sundials.hpp"
#include "program/timing.hpp"

#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// y = (x, v) for SUNDIALS: y' = (v, f(x, v) / m), and its Jacobian [[0, I], [df/dx / m, df/dv / m]] in
// compressed columns with every diagonal entry stored (SUNDIALS forms I - gamma J in place).
struct ClothSystem {
  ForceField& field;
  int n;  // free coordinates
  double mass;
  SparseMatrix dfdx, dfdv;
  Vector f;
  long long rhs_evaluations = 0, jacobian_evaluations = 0;

  explicit ClothSystem(ForceField& fld)
      : field(fld), n(fld.dof_count()), mass(fld.scene().params().mass), dfdx(fld.pattern()), dfdv(fld.pattern()),
        f(fld.dof_count()) {}

  [[nodiscard]] sunindextype nonzeros() const { return 2 * n + 2 * static_cast<sunindextype>(dfdx.nonZeros()); }

  // Each callback first honours a stop request (SIGINT, SIGTERM): the integration then ends within one
  // evaluation, however long the run (program/sundials.hpp).
  static int rhs(realtype /*t*/, N_Vector y, N_Vector ydot, void* data) {
    if (const int stop = sundials_stop_requested()) return stop;
    auto& s = *static_cast<ClothSystem*>(data);
    const Eigen::Map<const Vector> x(N_VGetArrayPointer(y), s.n), v(N_VGetArrayPointer(y) + s.n, s.n);
    Eigen::Map<Vector> dx(N_VGetArrayPointer(ydot), s.n), dv(N_VGetArrayPointer(ydot) + s.n, s.n);
    s.field.forces(x, v, s.f);
    dx = v;
    dv = s.f / s.mass;
    ++s.rhs_evaluations;
    return 0;
  }

  static int jacobian(realtype /*t*/, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* data, N_Vector /*tmp1*/,
                      N_Vector /*tmp2*/, N_Vector /*tmp3*/) {
    if (const int stop = sundials_stop_requested()) return stop;
    auto& s = *static_cast<ClothSystem*>(data);
    const Eigen::Map<const Vector> x(N_VGetArrayPointer(y), s.n), v(N_VGetArrayPointer(y) + s.n, s.n);
    s.field.jacobians(x, v, s.dfdx, s.dfdv);
    ++s.jacobian_evaluations;
    sunindextype* start = SUNSparseMatrix_IndexPointers(J);
    sunindextype* row = SUNSparseMatrix_IndexValues(J);
    realtype* value = SUNSparseMatrix_Data(J);
    sunindextype k = 0;
    const auto column = [&](int c, const SparseMatrix& block, double diagonal) {
      start[c] = k;
      row[k] = c < s.n ? c : c - s.n;  // the upper block's entry: 0 (x columns) or I (v columns)
      value[k++] = diagonal;
      const int bc = c < s.n ? c : c - s.n;
      for (SparseMatrix::InnerIterator it(block, bc); it; ++it) {
        row[k] = s.n + it.row();
        value[k++] = it.value() / s.mass;
      }
    };
    for (int c = 0; c < s.n; ++c) column(c, s.dfdx, 0.0);
    for (int c = s.n; c < 2 * s.n; ++c) column(c, s.dfdv, 1.0);
    start[2 * s.n] = k;
    return 0;
  }
};

struct Outcome {
  bool ok = false;
  SundialsEnd end;  // the status in the model page's terms, and SUNDIALS' own flag
  double seconds = 0;  // the thread's processor time of the integration alone
  long steps = 0, newton_iterations = 0, setups = 0, convergence_failures = 0;
  long long rhs_evaluations = 0, jacobian_evaluations = 0;  // the right-hand side's and the Jacobian's
  double t = 0, failed_t = 0;  // the time reached; the time the step that failed was heading for
};

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
// CVODE BDF (orders 1-5, variable step) or ARKODE (its default third-order ESDIRK of Kennedy & Carpenter, or the
// one-stage backward Euler table at the fixed step h), KLU on the analytic Jacobian, to T.
Outcome integrate(const std::string& solver, ClothSystem& system, N_Vector y, double T, double rtol, double atol,
                  double h, int max_order, SUNContext context) {
  const sunindextype N = 2 * system.n;
  SUNMatrix A = allocated(SUNSparseMatrix(N, N, system.nonzeros(), CSC_MAT, context));
  SUNLinearSolver klu = SUNLinSol_KLU(y, A, context);
  if (klu == nullptr) SUNMatDestroy(A);
  allocated(klu);
  Outcome out;
  realtype t = 0;
  int flag = 0;
  const double start = thread_cpu_seconds();
  if (solver == "cvode-bdf") {
    void* mem = allocated(CVodeCreate(CV_BDF, context));
    check(CVodeSetErrFile(mem, nullptr), "CVodeSetErrFile");  // a failure is reported in run.txt's terms
    check(CVodeInit(mem, ClothSystem::rhs, 0.0, y), "CVodeInit");
    check(CVodeSStolerances(mem, rtol, atol), "CVodeSStolerances");
    check(CVodeSetUserData(mem, &system), "CVodeSetUserData");
    check(CVodeSetLinearSolver(mem, klu, A), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(mem, ClothSystem::jacobian), "CVodeSetJacFn");
    check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
    if (max_order < 5) check(CVodeSetMaxOrd(mem, max_order), "CVodeSetMaxOrd");
    flag = CVode(mem, T, y, &t, CV_NORMAL);  // its own Nordsieck interpolant of order q gives y(T)
    out.t = t;
    read_counters(mem, {CVodeGetNumSteps, CVodeGetNumNonlinSolvConvFails, CVodeGetNumNonlinSolvIters,
                        CVodeGetNumLinSolvSetups, CVodeGetCurrentStep}, out);
    CVodeFree(&mem);
  } else {
    void* mem = allocated(ARKStepCreate(nullptr, ClothSystem::rhs, 0.0, y, context));
    check(ARKStepSetErrFile(mem, nullptr), "ARKStepSetErrFile");
    check(ARKStepSStolerances(mem, rtol, atol), "ARKStepSStolerances");
    check(ARKStepSetUserData(mem, &system), "ARKStepSetUserData");
    check(ARKStepSetLinearSolver(mem, klu, A), "ARKStepSetLinearSolver");
    check(ARKStepSetJacFn(mem, ClothSystem::jacobian), "ARKStepSetJacFn");
    check(ARKStepSetMaxNumSteps(mem, 1000000), "ARKStepSetMaxNumSteps");
    ARKodeButcherTable euler = nullptr;
    if (solver == "arkode-backward-euler") {
      // SUNDIALS 6.4 has no built-in backward Euler table: c = A = b = 1, no embedding, fixed steps.
      realtype c[] = {1}, a[] = {1}, b[] = {1};
      euler = allocated(ARKodeButcherTable_Create(1, 1, 0, c, a, b, nullptr));
      check(ARKStepSetTables(mem, 1, 0, euler, nullptr), "ARKStepSetTables");
      check(ARKStepSetFixedStep(mem, h), "ARKStepSetFixedStep");
      // A fixed step cannot shrink when Newton needs more than ARKODE's default 3 iterations, so it gets the
      // iteration limit ch09_implicit_runge_kutta has (20).
      check(ARKStepSetMaxNonlinIters(mem, 20), "ARKStepSetMaxNonlinIters");
      // One step at a time, the last one shortened to end on T: ARKODE's output at T is then its own step's
      // solution, not its interpolant (which halves the step's change: the difference measured in Chapter 9).
      flag = arkode_fixed_steps_to(mem, T, h, y, t);
    } else {
      check(ARKStepSetTableNum(mem, ARKODE_ARK324L2SA_DIRK_4_2_3, ARKODE_ERK_NONE), "ARKStepSetTableNum");
      flag = ARKStepEvolve(mem, T, y, &t, ARK_NORMAL);
    }
    out.t = t;
    read_counters(mem, {ARKStepGetNumSteps, ARKStepGetNumNonlinSolvConvFails, ARKStepGetNumNonlinSolvIters,
                        ARKStepGetNumLinSolvSetups, ARKStepGetCurrentStep}, out);
    if (euler) out.failed_t = std::min(t + h, T);  // the fixed step that failed (ARKODE's current step has moved on)
    ARKStepFree(&mem);
    if (euler) ARKodeButcherTable_Free(euler);
  }
  out.seconds = thread_cpu_seconds() - start;
  out.rhs_evaluations = system.rhs_evaluations;
  out.jacobian_evaluations = system.jacobian_evaluations;
  const bool finite = Eigen::Map<const Vector>(N_VGetArrayPointer(y), N).allFinite();
  out.end = sundials_end(flag, solver == "cvode-bdf", finite);
  out.ok = out.end.status == RunStatus::ok;
  SUNLinSolFree(klu);
  SUNMatDestroy(A);
  return out;
}
// [sundials_runs]

// One SUNDIALS run of the scene from its initial state: the outcome and the final free positions and velocities.
Outcome sundials_run(const std::string& solver, ForceField& field, double T, double rtol, double atol, double h,
                     Vector& x, Vector& v, int max_order = 5) {
  ClothSystem system(field);
  SUNContext context = nullptr;
  check(SUNContext_Create(nullptr, &context), "SUNContext_Create");
  N_Vector y = N_VNew_Serial(2 * system.n, context);
  if (y == nullptr) SUNContext_Free(&context);
  allocated(y);
  Eigen::Map<Vector>(N_VGetArrayPointer(y), system.n) = field.scene().initial_positions();
  Eigen::Map<Vector>(N_VGetArrayPointer(y) + system.n, system.n) = field.scene().initial_velocities();
  Outcome out = integrate(solver, system, y, T, rtol, atol, h, max_order, context);
  x = Eigen::Map<const Vector>(N_VGetArrayPointer(y), system.n);
  v = Eigen::Map<const Vector>(N_VGetArrayPointer(y) + system.n, system.n);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return out;
}

// The free particles' positions at T by RK4 at h_ref: explicit, sharing no code with either side.
Vector rk4_positions(ForceField& field, double T, double h_ref) {
  const auto rk4 = make_stepper("rk4", field);
  RunSettings run;
  run.dt = h_ref;
  run.t_end = T;
  run.stop = &interrupt_flag();
  const RunResult r = simulate(*rk4, run, false);
  throw_if_interrupted();
  if (r.status != RunStatus::ok) throw std::runtime_error("the RK4 reference failed: " + r.message);
  return r.x;
}

// One run of the comparison: who ran, with what, the error it reached and the processor seconds it took.
struct Timed {
  std::string solver, setting;
  double error = NAN, seconds = INFINITY;
  // The work: factorizations (SUNDIALS: linear solver setups), Jacobian evaluations, Newton iterations and
  // evaluations of the forces.
  long long factorizations = 0, jacobians = 0, newton_iterations = 0, forces = 0;
};

// A registered implicit method at the fixed step h, modified Newton stopped at newton_tol: best of `repeats`.
Timed project_run(ForceField& field, const std::string& method, double h, double newton_tol, NewtonVariant variant,
                  double T, const Vector& reference, int repeats, Vector* x_out = nullptr) {
  MethodSettings settings;
  settings.newton.variant = variant;
  settings.newton.tolerance = newton_tol;
  Timed t{method, "h = " + format_number(h) + ", " + newton_variant_name(variant) + " Newton, tol " +
                      format_number(newton_tol)};
  RunSettings run;
  run.dt = h;
  run.t_end = T;
  run.stop = &interrupt_flag();
  for (int k = 0; k < repeats; ++k) {
    const auto stepper = make_newton_stepper(method, field, settings);
    const double start = thread_cpu_seconds();
    const RunResult r = simulate(*stepper, run, false);
    // An interrupted study stops here: the tables are written only once every run is whole, so none lists a run
    // that did not finish.
    throw_if_interrupted();
    t.seconds = std::min(t.seconds, thread_cpu_seconds() - start);
    if (r.status != RunStatus::ok) return t;
    t.factorizations = r.counters.factorizations;
    t.jacobians = r.counters.jacobian_assemblies;
    t.newton_iterations = r.counters.newton_iterations;
    t.forces = r.counters.rhs_evaluations;
    t.error = (r.x - reference).lpNorm<Eigen::Infinity>();
    if (x_out) *x_out = r.x;
  }
  return t;
}

// A controlled run of an embedded pair at the error tolerance `tol` from a first step of 1 ms: modified Newton on
// the stage equations as they are, stopped at a tenth of tol (the chapter's defaults for a controlled run).
Timed controlled_run(ForceField& field, const std::string& method, double tol, double T, const Vector& reference,
                     int repeats) {
  Configuration c;
  c.method = method;
  c.settings.newton.variant = NewtonVariant::modified;
  c.settings.newton.line_search = LineSearch::residual;
  c.settings.newton.tolerance = 0.1 * tol;
  c.settings.newton.estimate_test = true;
  Timed t{configuration_name(c), "tol = " + format_number(tol, 3)};
  RunSettings run;
  run.dt = 1e-3;
  run.t_end = T;
  run.frames = 1;
  run.stop = &interrupt_flag();
  StepControl control;
  control.tolerance = tol;
  for (int k = 0; k < repeats; ++k) {
    DiagonallyImplicitRungeKutta stepper(field, builtin_implicit_tableau(method), c.settings.newton);
    const double start = thread_cpu_seconds();
    const ControlledRun r = simulate_controlled(stepper, run, control);
    t.seconds = std::min(t.seconds, thread_cpu_seconds() - start);
    throw_if_interrupted();
    if (r.result.status != RunStatus::ok) return t;
    t.factorizations = r.result.counters.factorizations;
    t.jacobians = r.result.counters.jacobian_assemblies;
    t.newton_iterations = r.result.counters.newton_iterations;
    t.forces = r.result.counters.rhs_evaluations;
    t.error = largest_distance(r.result.x, reference);
  }
  return t;
}

// One CVODE run (BDF up to `max_order`, KLU, the analytic Jacobian) at rtol = atol = tol: best of `repeats`.
Timed cvode_run(ForceField& field, int max_order, double tol, double T, const Vector& reference, int repeats) {
  Timed t{max_order < 5 ? "CVODE BDF, order <= " + std::to_string(max_order) : std::string("CVODE BDF"),
          "rtol = atol = " + format_number(tol, 3)};
  for (int k = 0; k < repeats; ++k) {
    Vector x, v;
    const Outcome out = sundials_run("cvode-bdf", field, T, tol, tol, 0, x, v, max_order);
    throw_if_interrupted();
    t.seconds = std::min(t.seconds, out.seconds);
    if (!out.ok) return t;
    t.error = largest_distance(x, reference);
    t.factorizations = out.setups;
    t.jacobians = out.jacobian_evaluations;
    t.newton_iterations = out.newton_iterations;
    t.forces = out.rhs_evaluations;
  }
  return t;
}

/// Both sides' runs on the stiff cloth: CVODE's at each tolerance, the book's at each tolerance or step.
struct StiffRuns {
  std::vector<Timed> cvode, book;
  int repeats = 1;
  double reference_change = 0;  // how far the reference moves when its step is halved [m]
};

// [speed_comparison]
// On the stiff cloth (5000, 20) over T = 0.4 s: CVODE's BDF (orders 1-5, and capped at 2) and the book's embedded
// pairs at the tolerances 10^(-k/4), and the book's SDIRKs at a ladder of fixed steps.
StiffRuns stiff_runs(const SceneParams& base, bool quick) {
  SceneParams p = base;
  p.stiffness = 5000;
  p.damping = 20;
  const double T = 0.4;
  StiffRuns runs;
  runs.repeats = quick ? 1 : 3;
  const Scene scene(p);
  ForceField field(scene);
  const Vector reference = rk4_positions(field, T, 2e-5);
  runs.reference_change = largest_distance(reference, rk4_positions(field, T, 1e-5));
  // The quick run (the plots target) takes every fourth rung (1e-2, 1e-3, ...), CVODE at its default orders and
  // the two ESDIRK pairs only; the full run every rung, CVODE also capped at order 2, TR-BDF2 and fixed steps.
  const int k_step = quick ? 4 : 1;
  for (int k = 8; k <= 28; k += k_step)
    for (const int max_order : {5, 2})
      if (!quick || max_order == 5)
        runs.cvode.push_back(cvode_run(field, max_order, std::pow(10.0, -k / 4.0), T, reference, runs.repeats));
  for (const char* pair : {"trbdf2", "esdirk32", "esdirk43"})
    for (int k = 4; k <= 24; k += k_step)
      if (!quick || std::string(pair) != "trbdf2")
        runs.book.push_back(controlled_run(field, pair, std::pow(10.0, -k / 4.0), T, reference, runs.repeats));
  if (quick) return runs;
  const struct {
    const char* method;
    double h, newton_tol;
  } book_runs[] = {{"sdirk2", 0.005, 1e-4},   {"sdirk2", 0.0025, 1e-4}, {"sdirk3", 0.0025, 1e-4},
                   {"sdirk3", 0.0016, 1e-4},  {"sdirk3", 0.00125, 1e-4}, {"sdirk3", 0.0008, 1e-5},
                   {"sdirk3", 0.000625, 1e-5}};
  for (const auto& r : book_runs)
    runs.book.push_back(project_run(field, r.method, r.h, r.newton_tol, NewtonVariant::modified, T, reference, runs.repeats));
  return runs;
}

// For an error level, the fastest of `runs` that reaches it (nullptr when none does).
const Timed* fastest_reaching(const std::vector<Timed>& runs, double level) {
  const Timed* best = nullptr;
  for (const Timed& t : runs)
    if (t.error <= level && (best == nullptr || t.seconds < best->seconds)) best = &t;
  return best;
}
// [speed_comparison]

// Every run into stiff_runs.dat (the figure); for each error level the fastest run of each side and the ratio of
// their processor times into stiff_comparison.md, and their work into stiff_work.md (the page's tables).
void stiff_comparison(const SceneParams& base, bool quick, const std::string& dir, const std::string& command) {
  const StiffRuns runs = stiff_runs(base, quick);
  OutputFile all(dir + "/stiff_runs.dat");
  std::fprintf(all.get(), "# stiff cloth K = 5000, D = 20, T = 0.4 s; error against RK4 at h = 2e-5 [m] (which moves "
               "%.2e m at h = 1e-5), thread processor seconds (best of %d)\n# index 0: CVODE BDF + KLU, index 1: "
               "the book's methods\n# error seconds factorizations jacobians newton_iterations forces \"run\"\n",
               runs.reference_change, runs.repeats);
  for (const auto* side : {&runs.cvode, &runs.book}) {
    for (const Timed& t : *side)
      std::fprintf(all.get(), "%.6e %.6f %lld %lld %lld %lld \"%s, %s\"\n", t.error, t.seconds, t.factorizations,
                   t.jacobians, t.newton_iterations, t.forces, t.solver.c_str(), t.setting.c_str());
    std::fprintf(all.get(), "\n\n");
  }
  // Index 2 and 3: for each level 10^(-k/4), the time of each side's fastest run reaching it (the diagram's lines).
  for (const auto* side : {&runs.cvode, &runs.book}) {
    for (int k = 8; k <= 24; ++k)
      if (const Timed* t = fastest_reaching(*side, std::pow(10.0, -k / 4.0)))
        std::fprintf(all.get(), "%.6e %.6f\n", std::pow(10.0, -k / 4.0), t->seconds);
    std::fprintf(all.get(), "\n\n");
  }
  all.commit();
  MarkdownTable table({"error level [m]", "CVODE's fastest run reaching it", "error [m]", "time [s]",
                       "the book's fastest run reaching it", "error [m]", "time [s]", "time ratio"},
                      "rlrrlrrr");
  // CVODE's factorizations are its linear solver setups (each a new I - gamma J factored by KLU).
  MarkdownTable work({"error level [m]", "run", "factorizations", "Jacobians", "Newton iterations",
                      "force evaluations"},
                     "rlrrrr");
  for (const double level : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    const Timed* c = fastest_reaching(runs.cvode, level);
    const Timed* b = fastest_reaching(runs.book, level);
    const auto cells = [](const Timed* t) -> std::vector<std::string> {
      if (t == nullptr) return {"none", "", ""};
      return {t->solver + ", " + t->setting, format_number(t->error, 2), format_number(t->seconds, 2)};
    };
    std::vector<std::string> row = {format_number(level)};
    for (const std::string& cell : cells(c)) row.push_back(cell);
    for (const std::string& cell : cells(b)) row.push_back(cell);
    row.push_back(c && b ? format_number(b->seconds / c->seconds, 2) : "");
    table.add_row(row);
    for (const Timed* t : {c, b})
      if (t != nullptr)
        work.add_row({format_number(level), t->solver + ", " + t->setting, std::to_string(t->factorizations),
                      std::to_string(t->jacobians), std::to_string(t->newton_iterations), std::to_string(t->forces)});
  }
  write_table_fragment(dir + "/stiff_comparison.md", table, command);
  write_table_fragment(dir + "/stiff_work.md", work, command);
  write_text_fragment(dir + "/stiff_reference.md",
                      "The reference is RK4 at h = 2·10⁻⁵ s; at h = 10⁻⁵ s it moves by " +
                          format_number(runs.reference_change, 2) + " m, so it is good to that order at every "
                          "level of the table.\n");
}

// On the report scene (200, 20), implicit Euler at h = 0.01 s over T = 1 s: ARKODE given the one-stage table at
// that fixed step, and the book's implicit Euler with full and with modified Newton; the time of each, and how far
// each ends from the book's implicit Euler solved to 1e-12.
void report_scene_comparison(const SceneParams& base, bool quick, const std::string& dir, const std::string& command) {
  SceneParams p = base;
  p.stiffness = 200;
  p.damping = 20;
  const double T = 1, h = 0.01;
  const int repeats = quick ? 1 : 3;
  const Scene scene(p);
  ForceField field(scene);
  Vector tight_x;
  project_run(field, "implicit_euler", h, 1e-12, NewtonVariant::full, T, Vector::Zero(field.dof_count()), 1, &tight_x);
  MarkdownTable table({"implicit Euler, h = 0.01 s, (K, D) = (200, 20), T = 1 s", "Newton tolerance", "time [s]",
                       "time / ARKODE's", "largest distance from the tightly solved solution [m]"},
                      "llrrr");
  double arkode_seconds = INFINITY;
  Vector x, v;
  Outcome out;
  for (int k = 0; k < repeats; ++k) {
    out = sundials_run("arkode-backward-euler", field, T, 1e-8, 1e-8, h, x, v);
    throw_if_interrupted();
    arkode_seconds = std::min(arkode_seconds, out.seconds);
  }
  table.add_row({"ARKODE, one-stage table, fixed step, KLU", "rtol = atol = 1e-8", format_number(arkode_seconds, 2),
                 "1", out.ok ? format_number((x - tight_x).lpNorm<Eigen::Infinity>(), 2)
                        : std::string(run_status_name(out.end.status)) + ": " + out.end.reason});
  for (const NewtonVariant variant : {NewtonVariant::full, NewtonVariant::modified}) {
    const Timed t = project_run(field, "implicit_euler", h, 1e-8, variant, T, tight_x, repeats);
    table.add_row({std::string("the book's implicit_euler, ") + newton_variant_name(variant) + " Newton",
                   "`--newton-tol 1e-8`", format_number(t.seconds, 2), format_number(t.seconds / arkode_seconds, 2),
                   format_number(t.error, 2)});
  }
  write_table_fragment(dir + "/report_scene.md", table, command);
}

}  // namespace

int main(int argc, char** argv) {
  std::string solver = "cvode-bdf";
  double rtol = 1e-6, atol = 1e-6;
  bool compare = false, want_report_runs = false, quick = false;
  CommandLine cli("ch09_sundials_benchmark",
                  "Chapter 9: the cloth integrated by SUNDIALS (CVODE BDF, ARKODE ESDIRK, ARKODE backward Euler)\n"
                  "with KLU on the analytic Jacobian, for comparison with ch09_implicit_runge_kutta.");
  cli.add_value("--solver", "cvode-bdf|arkode-dirk|arkode-backward-euler",
                "CVODE's BDF, ARKODE's ARK3(2)4L[2]SA ESDIRK (both with step control), or backward Euler at the "
                "fixed step --dt (default cvode-bdf)",
                [&](const std::string& s) {
                  if (s != "cvode-bdf" && s != "arkode-dirk" && s != "arkode-backward-euler")
                    throw InputError("unknown solver '" + s + "': expected cvode-bdf, arkode-dirk or "
                                     "arkode-backward-euler");
                  solver = s;
                });
  cli.add_value("--rtol", "TOL", "SUNDIALS' relative tolerance (default 1e-6)", [&](const std::string& s) {
    rtol = parse_number(s);
    if (!(rtol > 0) || rtol >= 1) throw InputError("expected a number in (0, 1), got " + s);
  });
  cli.add_value("--atol", "TOL", "SUNDIALS' absolute tolerance (default 1e-6)", [&](const std::string& s) {
    atol = parse_number(s);
    if (!(atol > 0) || atol >= 1) throw InputError("expected a number in (0, 1), got " + s);
  });
  cli.add_switch("--compare", "afterwards, the largest position error at T against RK4 at h = 1e-5 (not timed)",
                 [&] { compare = true; });
  cli.add_switch("--report-runs",
                 "the chapter's comparisons: CVODE against the book's SDIRKs on (K, D) = (5000, 20) over T = 0.4 s, "
                 "and ARKODE's backward Euler against the book's on (200, 20) over T = 1 s (processor time, best of 3)",
                 [&] { want_report_runs = true; });
  cli.add_switch("--quick", "with --report-runs: one timing per run (the plots target)", [&] { quick = true; });
  // No --frames: the program writes final.dat and run.txt, no frames.
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--K-flexion", "--damping", "--damping-model", "--springs",
                  "--pins", "--v0", "--dt", "--t-end", "--out"});
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const std::vector<std::string> single_run = {"final.dat", "run.txt"};
    const std::vector<std::string> report_runs = {"stiff_runs.dat", "stiff_comparison.md", "stiff_work.md",
                                                  "stiff_reference.md", "report_scene.md"};
    const long long particles = static_cast<long long>(opt.scene.grid.M) * opt.scene.grid.N;
    const std::string grid = std::to_string(opt.scene.grid.M) + "x" + std::to_string(opt.scene.grid.N);
    // KLU's factors of the 6n first-order system, far more than an explicit run's vectors (parse's check).
    const auto require_klu_memory = [&] {
      require_memory(static_cast<double>(particles) * sundials_klu_bytes_per_particle(particles), "--grid",
                     "a SUNDIALS run with KLU on a " + grid + " grid", ": expected a smaller grid");
    };
    if (want_report_runs) {
      refuse_unused(opt, "--report-runs",
                    {"--solver", "--rtol", "--atol", "--compare", "--K", "--damping", "--dt", "--t-end"},
                    "its runs set their own solvers, tolerances, stiffness, damping, steps and horizons");
      require_klu_memory();
      prepare_outputs(opt.run.out_dir, report_runs, single_run);
      const std::string command = reader_command(argc, argv);
      stiff_comparison(opt.scene, quick, opt.run.out_dir, command);
      report_scene_comparison(opt.scene, quick, opt.run.out_dir, command);
      return 0;
    }
    if (quick) throw InputError("--quick: only with --report-runs");
    if (solver != "arkode-backward-euler" && opt.has("--dt"))
      throw InputError("--dt: " + solver + " chooses its own steps; --dt is the fixed step of --solver "
                       "arkode-backward-euler");
    require_klu_memory();
    const Scene scene(opt.scene);
    ForceField field(scene);
    prepare_outputs(opt.run.out_dir, single_run, report_runs);
    Vector x, v;
    const Outcome out = sundials_run(solver, field, opt.run.t_end, rtol, atol, opt.run.dt, x, v);
    std::string error = "not computed";
    if (compare && out.ok) {
      try {
        error = format_number((x - rk4_positions(field, opt.run.t_end, 1e-5)).lpNorm<Eigen::Infinity>(), 4);
      } catch (const Interrupted&) {
        error = "not computed: interrupted";  // the run itself finished; run.txt says interrupted all the same
      }
    }
    // The run in the model page's terms: the last good state, and how the run ended.
    RunResult result;
    result.steps = out.steps;
    result.t = out.t;
    if (out.end.status == RunStatus::interrupted) result.status = RunStatus::interrupted;
    else if (!out.ok) stop_run(result, out.end.status, out.end.failure, out.steps + 1, out.failed_t, out.end.reason);
    write_final(opt.run.out_dir + "/final.dat", scene, x, v);
    KeyValues kv = {{"method", solver},
                    {"K", format_number(opt.scene.stiffness, 10)},
                    {"damping", format_number(opt.scene.damping, 10)},
                    {"t_end", format_number(opt.run.t_end, 10)},
                    {"dt", solver == "arkode-backward-euler" ? format_number(opt.run.dt, 10) : "adaptive"},
                    {"rtol", format_number(rtol, 10)},
                    {"atol", format_number(atol, 10)},
                    {"linear_solver", "klu"},
                    {"jacobian", "analytic"},
                    {"steps", std::to_string(out.steps)},
                    {"t_reached", format_number(out.t, 10)},
                    {"convergence_failures", std::to_string(out.convergence_failures)},
                    {"processor_seconds", format_number(out.seconds, 4)},
                    {"newton_iterations", std::to_string(out.newton_iterations)},
                    {"linear_solver_setups", std::to_string(out.setups)},
                    {"error_vs_rk4", error},
                    {"sundials_flag", out.end.flag}};
    append_status(kv, result, interrupt_signal());
    write_key_values(opt.run.out_dir + "/run.txt", kv);
    if (!out.ok) return report_stop(result, solver, cli.program());
    std::printf("%s: %s, %ld steps to t = %g s in %.3f s of processor time, %ld Newton iterations (%ld convergence "
                "failures), %ld setups, error %s m\n",
                cli.program().c_str(), solver.c_str(), out.steps, out.t, out.seconds, out.newton_iterations,
                out.convergence_failures, out.setups, error.c_str());
    return 0;
  });
}
