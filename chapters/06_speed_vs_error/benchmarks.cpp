// The micro-benchmarks of Chapter 6 (see benchmarks.hpp). Every timed body runs on buffers sized beforehand.
#include "benchmarks.hpp"

#include "hand_rk4.hpp"

#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/timing.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#ifdef CLOTH_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

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
  const RunResult r = simulate(*rk4, run, false);
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

Benchmark make(std::string name, const Timing& t, double count = 0, std::string unit = "") {
  return {std::move(name), 1e6 * t.median_wall, 1e6 * t.median_cpu, 1e6 * t.fastest_cpu, 1e6 * t.slowest_cpu, count,
          std::move(unit)};
}

template <class Solver>
Benchmark factorization(const char* name, Solver& solver, const SparseMatrix& A, int runs) {
  solver.analyzePattern(A);  // the ordering and the symbolic factorization: once per scene, not timed
  return make(name, time_runs([&] { solver.factorize(A); }, {runs, 2}));
}

}  // namespace

std::vector<Benchmark> run_benchmarks(const SceneParams& params, int runs) {
  std::vector<Benchmark> out;
  const Scene scene(params);
  ForceField field(scene);
  const auto states = folded_trajectory(scene);
  const Vector& x = states[0].first;
  const Vector& v = states[0].second;
  const int n = field.dof_count();
  Vector f(n);
  const auto springs = static_cast<double>(scene.springs().size());

  out.push_back(make("force_evaluation", time_runs([&] { field.forces(x, v, f); }, {runs, 10, 200}), springs,
                     "springs"));
  SparseMatrix A = field.pattern();
  const auto nnz = static_cast<double>(A.nonZeros());
  out.push_back(make("newton_matrix_refill_symmetric",
                     time_runs([&] { field.newton_matrix(x, v, h, StiffnessTreatment::symmetric, A); }, {runs, 5, 20}),
                     nnz, "nonzeros"));
  out.push_back(make("newton_matrix_refill_definite",
                     time_runs([&] { field.newton_matrix(x, v, h, StiffnessTreatment::definite, A); }, {runs, 5, 20}),
                     nnz, "nonzeros"));

  // Numeric factorizations of the definite matrix (positive definite, so LL^T works as well as LDL^T). First the
  // core's block factorization (integrators/block_ldu.hpp), symmetric and general, then what Eigen and CHOLMOD
  // offer on the same matrix.
  for (const auto symmetry : {BlockLDU::Symmetry::symmetric, BlockLDU::Symmetry::general}) {
    BlockLDU block;
    block.analyze(A, symmetry);
    const Timing t = time_runs([&] { block.factorize(A); }, {runs, 2, 5});
    const bool symmetric = symmetry == BlockLDU::Symmetry::symmetric;
    out.push_back(make(symmetric ? "factorize_block_ldlt_amd" : "factorize_block_ldu_amd", t,
                       block.factorization_flops(), "multiply_adds"));
  }
  {
    Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> s;
    out.push_back(factorization("factorize_eigen_sparselu_colamd", s, A, runs));
  }
  {
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> s;
    out.push_back(factorization("factorize_eigen_ldlt_amd", s, A, runs));
  }
  {
    Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> s;
    out.push_back(factorization("factorize_eigen_llt_amd", s, A, runs));
  }
  {
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> s;
    out.push_back(factorization("factorize_eigen_ldlt_natural", s, A, runs));
  }
#ifdef CLOTH_HAVE_CHOLMOD
  // CHOLMOD with one ordering each (its default tries several and keeps the least fill).
  const auto cholmod = [&](auto& s, const char* name, int ordering) {
    s.cholmod().nmethods = 1;
    s.cholmod().method[0].ordering = ordering;
    Benchmark b = factorization(name, s, A, runs);
    b.count = s.cholmod().lnz;
    b.count_name = "factor_nonzeros";
    out.push_back(b);
  };
  {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> s;
    cholmod(s, "factorize_cholmod_supernodal_amd", CHOLMOD_AMD);
  }
  {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> s;
    cholmod(s, "factorize_cholmod_supernodal_metis", CHOLMOD_METIS);
  }
  {
    Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Lower> s;
    cholmod(s, "factorize_cholmod_simplicial_amd", CHOLMOD_AMD);
  }
  {
    Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Lower> s;
    cholmod(s, "factorize_cholmod_simplicial_metis", CHOLMOD_METIS);
  }
#endif

  // Eigen's CG on the first Newton system of a step, cold (from 0) and warm (from the previous step's update).
  {
    Vector fx(n), r(n), dv_prev(n), dv(n);
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>> cg;
    cg.setTolerance(1e-8);
    const auto system = [&](const Vector& xs, const Vector& vs) {
      field.newton_matrix(xs + h * vs, vs, h, StiffnessTreatment::definite, A);
      field.forces(xs + h * vs, vs, fx);
      r = h * fx;
      cg.compute(A);
    };
    system(states[0].first, states[0].second);
    dv_prev = cg.solve(r);
    system(states[1].first, states[1].second);
    const Timing cold = time_runs([&] { dv = cg.solve(r); }, {runs, 2, 5});
    const auto cold_it = static_cast<double>(cg.iterations());
    const Timing warm = time_runs([&] { dv = cg.solveWithGuess(r, dv_prev); }, {runs, 2, 5});
    const auto warm_it = static_cast<double>(cg.iterations());
    out.push_back(make("cg_eigen_jacobi_cold_1e-8", cold, cold_it, "iterations"));
    out.push_back(make("cg_eigen_jacobi_warm_1e-8", warm, warm_it, "iterations"));
    // The same two solves with the core's allocation-free block-Jacobi PCG (integrators/pcg.hpp).
    BlockJacobiPCG pcg(n);
    const Timing precondition = time_runs([&] { pcg.compute(A); }, {runs, 2, 20});
    const Timing pcg_cold = time_runs(
        [&] {
          dv.setZero();
          pcg.solve(A, r, dv, 1e-8, 1000);
        }, {runs, 2, 5});
    const auto pcg_cold_it = static_cast<double>(pcg.iterations());
    const Timing pcg_warm = time_runs(
        [&] {
          dv = dv_prev;
          pcg.solve(A, r, dv, 1e-8, 1000);
        }, {runs, 2, 5});
    const auto pcg_warm_it = static_cast<double>(pcg.iterations());
    out.push_back(make("pcg_block_jacobi_setup", precondition));
    out.push_back(make("pcg_block_jacobi_cold_1e-8", pcg_cold, pcg_cold_it, "iterations"));
    out.push_back(make("pcg_block_jacobi_warm_1e-8", pcg_warm, pcg_warm_it, "iterations"));
  }

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
    const Timing t = time_runs(next, {runs, 0, static_cast<int>(states.size()) - 1});
    out.push_back(make(name, t,
                       static_cast<double>(ie.counters().cg_iterations) / static_cast<double>(ie.counters().steps),
                       "cg_iterations_per_solve"));
  };
  newton_iteration(LinearSolverKind::ldlt, "newton_iteration_ldlt");
  // The exact Jacobian, with the solvers a damped cloth's non-symmetric matrix needs (this scene's may be undamped,
  // its matrix then symmetric, but the general factorizations do not know it and do their full work).
  newton_iteration(LinearSolverKind::ldu, "newton_iteration_ldu_exact", StiffnessTreatment::exact);
  newton_iteration(LinearSolverKind::lu, "newton_iteration_sparselu_exact", StiffnessTreatment::exact);
  newton_iteration(LinearSolverKind::cg, "newton_iteration_cg_warm");

  // Runge-Kutta: the generic tableau engine against RK4 and explicit Euler written out by hand, on the same forces.
  {
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
          }, {runs, 5, 50});
    };
    // Interleaved, twice each, so that a slow spell of the machine favours neither; the faster of the two kept.
    const Timing g1 = time_step(*generic), h1 = time_step(hand), g2 = time_step(*generic), h2 = time_step(hand);
    const auto faster = [](const Timing& a, const Timing& b) { return a.median_cpu < b.median_cpu ? a : b; };
    out.push_back(make("rk4_step_tableau", faster(g1, g2), 4, "rhs_evaluations"));
    out.push_back(make("rk4_step_hand_unrolled", faster(h1, h2), 4, "rhs_evaluations"));
    const Timing e1 = time_step(*euler), u1 = time_step(hand_euler), e2 = time_step(*euler),
                  u2 = time_step(hand_euler);
    out.push_back(make("explicit_euler_step", faster(e1, e2), 1, "rhs_evaluations"));
    out.push_back(make("explicit_euler_step_hand_written", faster(u1, u2), 1, "rhs_evaluations"));
  }
  return out;
}

}  // namespace ch06
