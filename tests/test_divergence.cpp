// Runs that go wrong are results, not crashes: a diverging run stops with status 3, says at which step and time,
// and keeps its outputs up to the last sane state; a Newton step that fails is reported with its residual and is
// never accepted. Checked in the library (simulate, ImplicitEuler) and end to end (the chapter programs).
#include "model/force_field.hpp"
#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/run_outputs.hpp"
#include "program_runner.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace cloth_test;

namespace {

bool contains(const std::string& text, const std::string& piece) { return text.find(piece) != std::string::npos; }

/// Every whitespace-separated number of every data line of a file, or an empty list if one is not finite.
std::vector<double> finite_numbers(const fs::path& path, bool& all_finite) {
  std::vector<double> values;
  all_finite = true;
  for (const std::string& line : data_lines(path)) {
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      char* end = nullptr;
      const double x = std::strtod(w.c_str(), &end);
      if (end != w.c_str() + w.size() || !std::isfinite(x)) all_finite = false;
      values.push_back(x);
    }
  }
  return values;
}

/// Checks an output folder of a run that stopped early: final.dat a finite state of every particle, energy.dat
/// one finite line per completed step plus t = 0, and run.txt naming what happened: `status` (diverged or
/// step_failed), `failure` (the step failure's kind, or "" for none), `failed_step` one past the steps done, and a
/// reason. Returns the steps done.
long long check_kept_outputs(const fs::path& dir, int particles, const std::string& expected_status,
                             const std::string& expected_failure = "") {
  bool finite = false;
  const std::vector<std::string> final_lines = data_lines(dir / "final.dat");
  CHECK(final_lines.size() == static_cast<std::size_t>(particles));
  finite_numbers(dir / "final.dat", finite);
  CHECK(finite);
  const std::vector<std::string> energy_lines = data_lines(dir / "energy.dat");
  finite_numbers(dir / "energy.dat", finite);
  CHECK(finite);
  long long steps = -1, failed_step = -1;
  std::string status, failure, reason;
  for (const std::string& line : data_lines(dir / "run.txt")) {
    if (line.rfind("steps = ", 0) == 0) steps = std::atoll(line.c_str() + 8);
    if (line.rfind("failed_step = ", 0) == 0) failed_step = std::atoll(line.c_str() + 14);
    if (line.rfind("status = ", 0) == 0) status = line.substr(9);
    if (line.rfind("failure = ", 0) == 0) failure = line.substr(10);
    if (line.rfind("reason = ", 0) == 0) reason = line.substr(9);
  }
  CAPTURE(status);
  CHECK(status == expected_status);
  CHECK(failure == expected_failure);
  CHECK(!reason.empty());
  CHECK(steps >= 0);
  CHECK(failed_step == steps + 1);
  CHECK(energy_lines.size() == static_cast<std::size_t>(steps + 1));
  return steps;
}

}  // namespace

TEST_CASE("explicit Euler at K = 1e5, h = 0.01 diverges: the run stops at the first insane step and keeps the last sane state") {
  cloth::SceneParams p;
  p.stiffness = 1e5;
  const cloth::Scene scene(p);
  cloth::ForceField field(scene);
  const auto euler_stepper = cloth::make_stepper("explicit_euler", field);
  cloth::Stepper& euler = *euler_stepper;
  cloth::RunSettings rs;
  rs.dt = 0.01;
  rs.t_end = 1.0;
  const cloth::RunResult r = cloth::simulate(euler, rs);

  // h sqrt(K/m) = 3.2 is far beyond explicit Euler's (nonexistent) stability on oscillations: it must blow up
  // well before the 100 steps, and not in the first step (the first steps only grow the error).
  REQUIRE(r.status == cloth::RunStatus::diverged);
  CHECK(r.steps >= 1);
  CHECK(r.steps < 100);
  CHECK(r.t == doctest::Approx(static_cast<double>(r.steps) * rs.dt).epsilon(1e-12));
  CAPTURE(r.message);
  CHECK(contains(r.message, "diverged at step " + std::to_string(r.steps + 1) + ", t = "));
  CHECK(r.x.allFinite());
  CHECK(r.v.allFinite());
  CHECK(cloth::divergence_reason(r.x, r.v, cloth::divergence_radius(scene, rs.t_end)).empty());
  CHECK(r.energy.size() == static_cast<std::size_t>(r.steps + 1));
  CHECK(r.energy.back().t == doctest::Approx(r.t).epsilon(1e-12));
  for (const cloth::Frame& f : r.frames) CHECK(f.t <= r.t + 1e-12);

  // The kept state is exactly the state after `steps` steps, and one more step is the insane one.
  const auto again_stepper = cloth::make_stepper("explicit_euler", field);
  cloth::Stepper& again = *again_stepper;
  cloth::Vector x = scene.initial_positions(), v = scene.initial_velocities();
  for (long long k = 0; k < r.steps; ++k) again.step(rs.dt, x, v);
  CHECK((x.array() == r.x.array()).all());
  CHECK((v.array() == r.v.array()).all());
  again.step(rs.dt, x, v);
  CHECK(!cloth::divergence_reason(x, v, cloth::divergence_radius(scene, rs.t_end)).empty());

  // The outputs of the stopped run are written and readable, and the exit status is 3.
  ScratchDir scratch;
  rs.out_dir = scratch.path().string();
  cloth::write_outputs(r, euler, rs);
  CHECK(check_kept_outputs(scratch.path(), scene.particle_count(), "diverged") == r.steps);
  CHECK(cloth::report(r, euler, "test") == 3);
}

TEST_CASE("Newton capped at 2 iterations on a stiff step fails, reports step, time and residual, and changes nothing") {
  // h^2 K / m = 1: stiff enough that Newton needs more than 2 iterations to reach 1e-10, mild enough that it does.
  cloth::SceneParams p;
  p.stiffness = 1e4;
  p.grid = {8, 8, 0.1};
  const cloth::Scene scene(p);
  cloth::ForceField field(scene);
  const cloth::Vector x0 = scene.initial_positions(), v0 = scene.initial_velocities();

  // With the same tolerance the uncapped solver converges on this step, so the failure below is the cap's doing.
  cloth::NewtonSettings capped;
  capped.tolerance = 1e-10;
  {
    cloth::NewtonSettings uncapped = capped;
    uncapped.max_iterations = 20;
    cloth::ImplicitEuler full(field, uncapped);
    cloth::Vector x = x0, v = v0;
    REQUIRE(full.step(0.01, x, v));
    CHECK(full.residual_history().size() > 3);
  }

  capped.max_iterations = 2;
  cloth::ImplicitEuler newton(field, capped);
  cloth::Vector x = x0, v = v0;
  CHECK_FALSE(newton.step(0.01, x, v));
  CHECK((x.array() == x0.array()).all());
  CHECK((v.array() == v0.array()).all());
  const std::string reason = newton.failure().reason;
  CAPTURE(reason);
  CHECK(contains(reason, "did not converge in 2 iterations"));
  CHECK(contains(reason, "|r|_inf = "));
  // The residual it reports is the last one, and it is above the tolerance (else the step would have converged).
  const double residual = std::strtod(reason.c_str() + reason.find("|r|_inf = ") + 10, nullptr);
  CHECK(residual == doctest::Approx(newton.residual_history().back()).epsilon(1e-2));
  CHECK(residual > capped.tolerance);

  cloth::ImplicitEuler runner(field, capped);
  cloth::RunSettings rs;
  rs.dt = 0.01;
  rs.t_end = 0.1;
  const cloth::RunResult r = cloth::simulate(runner, rs);
  CHECK(r.status == cloth::RunStatus::step_failed);
  CHECK(r.failure == cloth::StepFailureKind::newton_not_converged);  // the run carries what stopped the step
  CHECK(r.steps == 0);
  CAPTURE(r.message);
  CHECK(contains(r.message, "step 1, t = 0.01"));
  CHECK(contains(r.message, "|r|_inf = "));
  CHECK((r.x.array() == x0.array()).all());
  CHECK(r.energy.size() == 1);
  CHECK(cloth::report(r, runner, "test") == 3);
}

TEST_CASE("a linear solve that fails inside Newton fails the step instead of being accepted") {
  cloth::SceneParams p;
  p.stiffness = 1e5;
  p.grid = {8, 8, 0.1};
  const cloth::Scene scene(p);
  cloth::ForceField field(scene);
  // One CG iteration cannot reach a 1e-15 relative residual on this stiff matrix: the solver reports
  // NoConvergence, and Newton must not use its half-solved update.
  cloth::NewtonSettings s;
  s.solver = cloth::LinearSolverKind::cg;
  s.treatment = cloth::StiffnessTreatment::definite;
  s.cg_max_iterations = 1;
  s.cg_tolerance = 1e-15;
  cloth::ImplicitEuler newton(field, s);
  const cloth::Vector x0 = scene.initial_positions(), v0 = scene.initial_velocities();
  cloth::Vector x = x0, v = v0;
  CHECK_FALSE(newton.step(0.01, x, v));
  CAPTURE(newton.failure().reason);
  CHECK(contains(newton.failure().reason, "linear solve (cg) failed in Newton iteration 1"));
  CHECK(contains(newton.failure().reason, "|r|_inf = "));
  CHECK((x.array() == x0.array()).all());
  CHECK((v.array() == v0.array()).all());
}

#ifdef CLOTH_HAVE_CH02_EXPLICIT_EULER
TEST_CASE("ch02_explicit_euler --K 100000 --t-end 1: status 3, step and time on stderr, sane outputs kept") {
  const ProgramFolder folder;
  const fs::path& cwd = folder.cwd();
  const ProgramRun run = folder.run("ch02_explicit_euler", {"--K", "100000", "--t-end", "1", "--out", "out"});
  CAPTURE(run.err);
  CHECK(run.status == 3);
  CHECK(contains(run.err, "diverged at step "));
  CHECK(contains(run.err, ", t = "));
  const long long steps = check_kept_outputs(cwd / "out", 400, "diverged");
  CHECK(steps < 100);
  CHECK(contains(run.err, "diverged at step " + std::to_string(steps + 1) + ","));
}
#endif

#ifdef CLOTH_HAVE_CH03_RUNGE_KUTTA
TEST_CASE("ch03_runge_kutta rk4 at K = 100000, h = 0.01 diverges: status 3 and the sane outputs kept") {
  // h sqrt(K/m) times the largest spring-network factor is far outside RK4's stability interval (|z| < 2.8).
  const ProgramFolder folder;
  const fs::path& cwd = folder.cwd();
  const ProgramRun run =
      folder.run("ch03_runge_kutta", {"--tableau", "rk4", "--K", "100000", "--t-end", "1", "--out", "out"});
  CAPTURE(run.err);
  CHECK(run.status == 3);
  CHECK(contains(run.err, "diverged at step "));
  CHECK(check_kept_outputs(cwd / "out", 400, "diverged") < 100);
}
#endif

#ifdef CLOTH_HAVE_CH04_IMPLICIT_EULER
TEST_CASE("ch04_implicit_euler with Newton capped at 2 iterations on a stiff cloth: status 3, never accepted") {
  const ProgramFolder folder;
  const fs::path& cwd = folder.cwd();
  const ProgramRun run = folder.run("ch04_implicit_euler", {"--K", "100000", "--grid", "8x8", "--t-end", "0.1",
                                                            "--newton-max-iter", "2", "--newton-tol", "1e-14", "--out", "out"});
  CAPTURE(run.err);
  CHECK(run.status == 3);
  CHECK(contains(run.err, "step 1, t = 0.01"));
  CHECK(contains(run.err, "|r|_inf = "));
  CHECK(contains(run.err, "step_failed (newton_not_converged) at step 1, t = 0.01 s: "));
  CHECK(check_kept_outputs(cwd / "out", 64, "step_failed", "newton_not_converged") == 0);
}
#endif
