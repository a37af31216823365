// The micro-benchmarks of Chapter 6 (see benchmarks.hpp). Every timed body runs on buffers sized beforehand.
#include "benchmarks.hpp"

#include "hand_rk4.hpp"

#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/timing.hpp"

#include <Eigen/IterativeLinearSolvers>

namespace ch06 {

using namespace cloth;

namespace {

constexpr double h = 0.01;  // the report's step, for every implicit quantity
constexpr int trajectory_length = 16;

// The cloth from t = 0.5 s on (RK4 with h = 1e-3 to get there, then implicit Euler steps of h): folded,
// springs compressed and stretched, the states a solver meets in a run, each one step after the other.
std::vector<std::pair<Vector, Vector>> folded_trajectory(const Scene& scene) {
  ForceField field(scene);
  const auto rk4 = make_stepper("rk4", field);
  RunSettings run;
  run.dt = 1e-3;
  run.t_end = 0.5;
  const RunResult r = simulate(*rk4, run, /*record=*/false);
  std::vector<std::pair<Vector, Vector>> states{{r.x, r.v}};
  MethodSettings settings;
  settings.newton.tolerance = 1e-10;
  settings.newton.solver = LinearSolverKind::ldlt;
  settings.newton.treatment = StiffnessTreatment::symmetric;
  const auto ie = make_stepper("implicit_euler", field, settings);
  Vector x = r.x, v = r.v;
  while (static_cast<int>(states.size()) < trajectory_length) {
    ie->step(h, x, v);
    states.emplace_back(x, v);
  }
  return states;
}

using States = std::vector<std::pair<Vector, Vector>>;

// One force evaluation and the two refills of the Newton matrix at the first folded state; A ends holding the
// definite matrix the factorizations below take.
void time_forces_and_refills(ForceField& field, const Vector& x, const Vector& v, SparseMatrix& A, int runs,
                             std::vector<Benchmark>& out) {
  Vector f(field.dof_count());
  const auto springs = static_cast<double>(field.scene().springs().size());
  const Timing force = time_runs([&] { field.forces(x, v, f); }, {.runs = runs, .warmup = 10, .repeat = 200});
  out.push_back(timed_benchmark("force_evaluation", force, springs, "springs"));
  const auto nnz = static_cast<double>(A.nonZeros());
  const TimingPlan refills{.runs = runs, .warmup = 5, .repeat = 20};
  const Timing symmetric =
      time_runs([&] { field.newton_matrix(x, v, h, StiffnessTreatment::symmetric, A); }, refills);
  out.push_back(timed_benchmark("newton_matrix_refill_symmetric", symmetric, nnz, "nonzeros"));
  const Timing definite = time_runs([&] { field.newton_matrix(x, v, h, StiffnessTreatment::definite, A); }, refills);
  out.push_back(timed_benchmark("newton_matrix_refill_definite", definite, nnz, "nonzeros"));
}

void time_conjugate_gradients(ForceField& field, const States& states, SparseMatrix& A, int runs,
                              std::vector<Benchmark>& out) {
  const int n = field.dof_count();
  const double cg_tolerance = 1e-8;  // the relative residual both solvers stop at (the benchmarks' names say 1e-8)
  const int cg_max_iterations = 1000;
  // Eigen's CG on the first Newton system of a step, cold (from 0) and warm (from the previous step's update).
  Vector fx(n), r(n), dv_prev(n), dv(n);
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>> cg;
  cg.setTolerance(cg_tolerance);
  const auto system = [&](const Vector& xs, const Vector& vs) {
    field.newton_matrix(xs + h * vs, vs, h, StiffnessTreatment::definite, A);
    field.forces(xs + h * vs, vs, fx);
    r = h * fx;
    cg.compute(A);
  };
  system(states[0].first, states[0].second);
  dv_prev = cg.solve(r);
  system(states[1].first, states[1].second);
  const Timing cold = time_runs([&] { dv = cg.solve(r); }, {.runs = runs, .warmup = 2, .repeat = 5});
  const auto cold_it = static_cast<double>(cg.iterations());
  const Timing warm =
      time_runs([&] { dv = cg.solveWithGuess(r, dv_prev); }, {.runs = runs, .warmup = 2, .repeat = 5});
  const auto warm_it = static_cast<double>(cg.iterations());
  out.push_back(timed_benchmark("cg_eigen_jacobi_cold_1e-8", cold, cold_it, "iterations"));
  out.push_back(timed_benchmark("cg_eigen_jacobi_warm_1e-8", warm, warm_it, "iterations"));
  // The same two solves with the core's allocation-free block-Jacobi PCG (integrators/pcg.hpp).
  BlockJacobiPCG pcg(n);
  const Timing precondition = time_runs([&] { pcg.compute(A); }, {.runs = runs, .warmup = 2, .repeat = 20});
  const Timing pcg_cold = time_runs(
      [&] {
        dv.setZero();
        pcg.solve(A, r, dv, cg_tolerance, cg_max_iterations);
      }, {.runs = runs, .warmup = 2, .repeat = 5});
  const auto pcg_cold_it = static_cast<double>(pcg.iterations());
  const Timing pcg_warm = time_runs(
      [&] {
        dv = dv_prev;
        pcg.solve(A, r, dv, cg_tolerance, cg_max_iterations);
      }, {.runs = runs, .warmup = 2, .repeat = 5});
  const auto pcg_warm_it = static_cast<double>(pcg.iterations());
  out.push_back(timed_benchmark("pcg_block_jacobi_setup", precondition));
  out.push_back(timed_benchmark("pcg_block_jacobi_cold_1e-8", pcg_cold, pcg_cold_it, "iterations"));
  out.push_back(timed_benchmark("pcg_block_jacobi_warm_1e-8", pcg_warm, pcg_warm_it, "iterations"));
}

void time_newton_iterations(const Scene& scene, const States& states, int runs, std::vector<Benchmark>& out) {
  const Vector& x = states[0].first;
  const Vector& v = states[0].second;
  // One Newton iteration of implicit Euler (force evaluation, refill, factorization or preconditioner, solve),
  // stepping through consecutive states so that CG's warm start is the one a run would see.
  const auto newton_iteration = [&](LinearSolverKind kind, const char* name,
                                    StiffnessTreatment treatment = StiffnessTreatment::definite) {
    ForceField f2(scene);
    MethodSettings one;  // Baraff & Witkin's single iteration: one assembly, factorization and solve per step
    one.newton.tolerance = 1e-8;
    one.newton.variant = NewtonVariant::one;
    one.newton.solver = kind;
    one.newton.treatment = treatment;
    const auto ie_stepper = make_stepper("implicit_euler", f2, one);
    Stepper& ie = *ie_stepper;
    Vector xs = x, vs = v;
    std::size_t i = 0;
    const auto next = [&] {
      i = (i + 1) % states.size();
      xs = states[i].first;
      vs = states[i].second;
      ie.step(h, xs, vs);
    };
    for (std::size_t k = 0; k < states.size(); ++k) next();
    ie.reset_counters();
    const Timing t = time_runs(next, {.runs = runs, .repeat = static_cast<int>(states.size()) - 1});
    out.push_back(timed_benchmark(name, t,
                       static_cast<double>(ie.counters().cg_iterations) / static_cast<double>(ie.counters().steps),
                       "cg_iterations_per_solve"));
  };
  newton_iteration(LinearSolverKind::ldlt, "newton_iteration_ldlt");
  // The exact Jacobian, with the solvers a damped cloth's non-symmetric matrix needs (this scene's may be undamped,
  // its matrix then symmetric, but the general factorizations do not know it and do their full work).
  newton_iteration(LinearSolverKind::ldu, "newton_iteration_ldu_exact", StiffnessTreatment::exact);
  newton_iteration(LinearSolverKind::lu, "newton_iteration_sparselu_exact", StiffnessTreatment::exact);
  newton_iteration(LinearSolverKind::cg, "newton_iteration_cg_warm");

}

void time_runge_kutta_steps(ForceField& field, const Vector& x, const Vector& v, int runs, std::vector<Benchmark>& out) {
  // Runge-Kutta: the generic tableau engine against RK4 and explicit Euler written out by hand, on the same forces.
  const auto generic = make_stepper("rk4", field);
  HandRK4 hand(field);
  const auto euler = make_stepper("explicit_euler", field);
  HandExplicitEuler hand_euler(field);
  Vector xs = x, vs = v;
  const auto time_step = [&](Stepper& s) {
    return time_runs(
        [&] {
          xs = x;
          vs = v;
          s.step(1e-4, xs, vs);
        }, {.runs = runs, .warmup = 5, .repeat = 50});
  };
  // Interleaved, twice each, so that a slow spell of the machine favours neither; the faster of the two kept.
  const Timing g1 = time_step(*generic), h1 = time_step(hand), g2 = time_step(*generic), h2 = time_step(hand);
  const auto faster = [](const Timing& a, const Timing& b) { return a.median_cpu < b.median_cpu ? a : b; };
  out.push_back(timed_benchmark("rk4_step_tableau", faster(g1, g2), 4, "rhs_evaluations"));
  out.push_back(timed_benchmark("rk4_step_hand_unrolled", faster(h1, h2), 4, "rhs_evaluations"));
  const Timing e1 = time_step(*euler), u1 = time_step(hand_euler), e2 = time_step(*euler),
                u2 = time_step(hand_euler);
  out.push_back(timed_benchmark("explicit_euler_step", faster(e1, e2), 1, "rhs_evaluations"));
  out.push_back(timed_benchmark("explicit_euler_step_hand_written", faster(u1, u2), 1, "rhs_evaluations"));
}

}  // namespace

std::vector<Benchmark> run_benchmarks(const SceneParams& params, int runs) {
  std::vector<Benchmark> out;
  const Scene scene(params);
  ForceField field(scene);
  const States states = folded_trajectory(scene);
  const Vector& x = states[0].first;
  const Vector& v = states[0].second;
  SparseMatrix A = field.pattern();
  time_forces_and_refills(field, x, v, A, runs, out);
  time_factorizations(A, runs, out);  // factorizations.cpp
  time_conjugate_gradients(field, states, A, runs, out);
  time_newton_iterations(scene, states, runs, out);
  time_runge_kutta_steps(field, x, v, runs, out);
  return out;
}

}  // namespace ch06
