// Chapter 9's reference point: the same cloth integrated by SUNDIALS (Hindmarsh et al. 2005; Gardner et al. 2022),
// CVODE's variable-order BDF and ARKODE's diagonally implicit methods, each Newton system solved by KLU (Davis &
// Palamadai Natarajan 2010) on the analytic sparse Jacobian of the model. The chapter compares its own methods
// with these runs.
#include "program/command_line.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/output.hpp"

#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

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

  static int rhs(realtype /*t*/, N_Vector y, N_Vector ydot, void* data) {
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
  std::string message;
  double seconds = 0;
  long steps = 0, newton_iterations = 0, setups = 0, convergence_failures = 0;
  double t = 0;
};

void check(int flag, const char* call) {
  if (flag < 0) throw InputError(std::string("SUNDIALS ") + call + " failed with flag " + std::to_string(flag));
}

// [sundials_runs]
// CVODE BDF (orders 1-5, variable step) or ARKODE (its default third-order ESDIRK of Kennedy & Carpenter, or the
// one-stage backward Euler table at the fixed step h), KLU on the analytic Jacobian, to T.
Outcome integrate(const std::string& solver, ClothSystem& system, N_Vector y, double T, double rtol, double atol,
                  double h, SUNContext context) {
  const sunindextype N = 2 * system.n;
  SUNMatrix A = SUNSparseMatrix(N, N, system.nonzeros(), CSC_MAT, context);
  SUNLinearSolver klu = SUNLinSol_KLU(y, A, context);
  Outcome out;
  realtype t = 0;
  const auto start = std::chrono::steady_clock::now();
  if (solver == "cvode-bdf") {
    void* mem = CVodeCreate(CV_BDF, context);
    check(CVodeInit(mem, ClothSystem::rhs, 0.0, y), "CVodeInit");
    check(CVodeSStolerances(mem, rtol, atol), "CVodeSStolerances");
    check(CVodeSetUserData(mem, &system), "CVodeSetUserData");
    check(CVodeSetLinearSolver(mem, klu, A), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(mem, ClothSystem::jacobian), "CVodeSetJacFn");
    check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
    const int flag = CVode(mem, T, y, &t, CV_NORMAL);
    out.ok = flag >= 0;
    out.message = out.ok ? "ok" : "CVode returned " + std::to_string(flag) + " at t = " + format_number(t, 6);
    CVodeGetNumSteps(mem, &out.steps);
    CVodeGetNumNonlinSolvConvFails(mem, &out.convergence_failures);
    out.t = t;
    CVodeGetNumNonlinSolvIters(mem, &out.newton_iterations);
    CVodeGetNumLinSolvSetups(mem, &out.setups);
    CVodeFree(&mem);
  } else {
    void* mem = ARKStepCreate(nullptr, ClothSystem::rhs, 0.0, y, context);
    check(ARKStepSStolerances(mem, rtol, atol), "ARKStepSStolerances");
    check(ARKStepSetUserData(mem, &system), "ARKStepSetUserData");
    check(ARKStepSetLinearSolver(mem, klu, A), "ARKStepSetLinearSolver");
    check(ARKStepSetJacFn(mem, ClothSystem::jacobian), "ARKStepSetJacFn");
    check(ARKStepSetMaxNumSteps(mem, 1000000), "ARKStepSetMaxNumSteps");
    ARKodeButcherTable euler = nullptr;
    if (solver == "arkode-backward-euler") {
      // SUNDIALS 6.4 has no built-in backward Euler table: c = A = b = 1, no embedding, fixed steps.
      realtype c[] = {1}, a[] = {1}, b[] = {1};
      euler = ARKodeButcherTable_Create(1, 1, 0, c, a, b, nullptr);
      check(ARKStepSetTables(mem, 1, 0, euler, nullptr), "ARKStepSetTables");
      check(ARKStepSetFixedStep(mem, h), "ARKStepSetFixedStep");
      // A fixed step cannot shrink when Newton needs more than ARKODE's default 3 iterations, so it gets the
      // iteration limit ch09_implicit_runge_kutta has (20).
      check(ARKStepSetMaxNonlinIters(mem, 20), "ARKStepSetMaxNonlinIters");
    } else {
      check(ARKStepSetTableNum(mem, ARKODE_ARK324L2SA_DIRK_4_2_3, ARKODE_ERK_NONE), "ARKStepSetTableNum");
    }
    const int flag = ARKStepEvolve(mem, T, y, &t, ARK_NORMAL);
    out.ok = flag >= 0;
    out.message = out.ok ? "ok" : "ARKStepEvolve returned " + std::to_string(flag) + " at t = " + format_number(t, 6);
    ARKStepGetNumSteps(mem, &out.steps);
    ARKStepGetNumNonlinSolvConvFails(mem, &out.convergence_failures);
    out.t = t;
    ARKStepGetNumNonlinSolvIters(mem, &out.newton_iterations);
    ARKStepGetNumLinSolvSetups(mem, &out.setups);
    ARKStepFree(&mem);
    if (euler) ARKodeButcherTable_Free(euler);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SUNLinSolFree(klu);
  SUNMatDestroy(A);
  return out;
}
// [sundials_runs]

}  // namespace

int main(int argc, char** argv) {
  std::string solver = "cvode-bdf";
  double rtol = 1e-6, atol = 1e-6;
  bool compare = false;
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
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const Scene scene(opt.scene);
    ForceField field(scene);
    ClothSystem system(field);
    prepare_output_dir(opt.run.out_dir);
    SUNContext context = nullptr;
    check(SUNContext_Create(nullptr, &context), "SUNContext_Create");
    N_Vector y = N_VNew_Serial(2 * system.n, context);
    Eigen::Map<Vector>(N_VGetArrayPointer(y), system.n) = scene.initial_positions();
    Eigen::Map<Vector>(N_VGetArrayPointer(y) + system.n, system.n) = scene.initial_velocities();
    const Outcome out = integrate(solver, system, y, opt.run.t_end, rtol, atol, opt.run.dt, context);
    const Vector x = Eigen::Map<const Vector>(N_VGetArrayPointer(y), system.n);
    const Vector v = Eigen::Map<const Vector>(N_VGetArrayPointer(y) + system.n, system.n);
    N_VDestroy(y);
    SUNContext_Free(&context);
    std::string error = "not computed";
    if (compare && out.ok) {
      const auto rk4 = make_stepper("rk4", field);
      RunSettings run;
      run.dt = 1e-5;
      run.t_end = opt.run.t_end;
      const RunResult reference = simulate(*rk4, run, false);
      error = format_number((x - reference.x).lpNorm<Eigen::Infinity>(), 4);
    }
    write_final(opt.run.out_dir + "/final.dat", scene, x, v);
    write_key_values(opt.run.out_dir + "/run.txt",
                     {{"method", solver},
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
                      {"wall_seconds", format_number(out.seconds, 4)},
                      {"rhs_evaluations", std::to_string(system.rhs_evaluations)},
                      {"jacobian_evaluations", std::to_string(system.jacobian_evaluations)},
                      {"newton_iterations", std::to_string(out.newton_iterations)},
                      {"linear_solver_setups", std::to_string(out.setups)},
                      {"error_vs_rk4", error},
                      {"status", out.message}});
    std::printf("%s: %s, %ld steps to t = %g s in %.3f s, %lld f, %lld J, %ld Newton iterations (%ld convergence "
                "failures), %ld setups, error %s m\n",
                cli.program().c_str(), solver.c_str(), out.steps, out.t, out.seconds, system.rhs_evaluations,
                system.jacobian_evaluations, out.newton_iterations, out.convergence_failures, out.setups,
                error.c_str());
    return out.ok ? 0 : 3;
  });
}
