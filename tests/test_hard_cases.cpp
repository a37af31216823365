// Chapter 7's hard cases: very stiff undamped springs, coincident particles, a cloth on one corner and a rigid
// rotation, a violent start, a 100 x 100 grid, and a 60 s run, each checked against what must hold.
#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"

#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <cmath>

using namespace cloth;

namespace {
RunResult run(const SceneParams& p, const std::string& method, double h, double T, NewtonSettings newton = {}) {
  const Scene scene(p);
  ForceField field(scene);
  auto stepper = make_stepper(method, field, {newton});
  RunSettings settings;
  settings.dt = h;
  settings.t_end = T;
  settings.frames = 1;
  return simulate(*stepper, settings, true);
}
bool energy_never_rises(const RunResult& r, double slack) {
  for (std::size_t k = 1; k < r.energy.size(); ++k)
    if (r.energy[k].energy.total() > r.energy[k - 1].energy.total() + slack) return false;
  return true;
}
}  // namespace

TEST_CASE("K = 1e5, D = 0, h = 0.01: explicit methods are reported diverged with step and time, never NaN") {
  SceneParams p;
  p.stiffness = 1e5;
  for (const std::string method : {"explicit_euler", "symplectic_euler", "rk4"}) {
    CAPTURE(method);
    const RunResult r = run(p, method, 0.01, 2.0);
    CHECK(r.status == RunStatus::diverged);
    CHECK(r.message.find("step") != std::string::npos);
    CHECK(r.message.find("t = ") != std::string::npos);
    CHECK(r.x.allFinite());  // the last sane state is what is kept
    CHECK(r.v.allFinite());
    for (const EnergySample& e : r.energy) CHECK(std::isfinite(e.energy.total()));
  }
  // Implicit Euler stays bounded and never gains energy (first 0.2 s: 20 steps of the same stiff problem).
  const RunResult r = run(p, "implicit_euler", 0.01, 0.2);
  CHECK(r.status == RunStatus::ok);
  CHECK(energy_never_rises(r, 1e-9 * r.energy.front().energy.total()));
}

TEST_CASE("coincident particles: a zero-length spring exerts no force and gives no NaN (degenerate_length_fraction)") {
  SceneParams p;
  p.grid.M = 3;
  p.grid.N = 3;
  p.pins = PinSet::none;
  p.damping = 5;
  const Scene scene(p);
  ForceField field(scene);
  Vector x = scene.initial_positions();
  Vector v = Vector::Random(scene.dof_count());
  x.segment<3>(3) = x.segment<3>(0);  // slots 0 and 1: particles (0,0) and (0,1), joined by a structural spring
  Vector f(scene.dof_count());
  field.forces(x, v, f);
  CHECK(f.allFinite());
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, v, dfdx, dfdv);
  CHECK(Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(dfdx.valuePtr(), dfdx.nonZeros())).allFinite());
  CHECK(Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(dfdv.valuePtr(), dfdv.nonZeros())).allFinite());
  // The energy still counts the collapsed spring: 1/2 K L0^2 is finite and is what pushes the particles apart
  // once they separate by more than 1e-12 L0.
  CHECK(std::isfinite(field.energy(x, v).total()));
  // An implicit step from there is finite too.
  auto stepper = make_stepper("implicit_euler", field);
  CHECK(stepper->step(0.01, x, v));
  CHECK(x.allFinite());
  CHECK(v.allFinite());
}

TEST_CASE("a rigid rotation: the projected damper exerts exactly zero force, the report-law damper slows it") {
  SceneParams p;
  p.grid.M = 6;
  p.grid.N = 5;
  p.pins = PinSet::none;
  p.gravity = 0;
  p.damping = 20;
  const Eigen::Vector3d omega(0.7, -1.3, 2.1);  // any axis: rotate about the sheet's centre
  const Eigen::Vector3d centre(0.25, 0.2, 0);
  for (DampingModel model : {DampingModel::projected, DampingModel::report}) {
    p.damping_model = model;
    const Scene scene(p);
    ForceField field(scene);
    const Vector x = scene.initial_positions();  // springs at rest length: no spring force
    Vector v(scene.dof_count());
    for (int s = 0; s < scene.free_count(); ++s) v.segment<3>(3 * s) = omega.cross(x.segment<3>(3 * s) - centre);
    Vector f(scene.dof_count());
    field.forces(x, v, f);
    const double power = f.dot(v);
    if (model == DampingModel::projected) {
      // (v_p - v_q) . u = (omega x d) . d / l = 0 for every spring.
      CHECK(f.lpNorm<Eigen::Infinity>() < 1e-12);
      CHECK(std::abs(power) < 1e-12);
    } else {
      CHECK(f.lpNorm<Eigen::Infinity>() > 1.0);
      CHECK(power < -1.0);  // -D l |v_p - v_q|^2 summed over springs: it brakes the rotation
    }
  }
}

TEST_CASE("a cloth pinned by one corner swings through a large rotation, finite, and its energy never rises") {
  SceneParams p;
  p.grid.M = 8;
  p.grid.N = 8;
  p.pins = PinSet::corner;
  p.stiffness = 200;
  p.damping = 2;
  const RunResult r = run(p, "implicit_euler", 0.01, 1.0);
  REQUIRE(r.status == RunStatus::ok);
  CHECK(r.x.allFinite());
  // The far corner (7,7), 0.99 m from the pin at rest, has swung down well below the pin: a large rotation.
  const Scene scene(p);
  const int far = scene.slot(scene.grid().particle(7, 7));
  CHECK(r.x[3 * far + 2] < -0.5);
  CHECK(energy_never_rises(r, 1e-9 * std::abs(r.energy.front().energy.total())));
}

TEST_CASE("a violent start, v0 = 200 m/s: implicit Euler stays finite and dissipative; explicit Euler is caught") {
  SceneParams p;
  p.grid.M = 10;
  p.grid.N = 10;
  p.stiffness = 200;
  p.initial_velocity_z = 200;
  const RunResult r = run(p, "implicit_euler", 0.01, 0.5);
  CHECK(r.status == RunStatus::ok);
  CHECK(r.x.allFinite());
  CHECK(energy_never_rises(r, 1e-9 * r.energy.front().energy.total()));
  const RunResult e = run(p, "explicit_euler", 0.01, 2.0);
  CHECK(e.x.allFinite());  // diverged or not, what is kept is a sane state
  if (e.status != RunStatus::ok) CHECK(e.message.find("step") != std::string::npos);
}

TEST_CASE("a 100 x 100 cloth with implicit Euler at h = 0.01: both linear solvers give finite, non-increasing energy") {
  SceneParams p;
  p.grid.M = 100;
  p.grid.N = 100;
  const Scene scene(p);
  ForceField field(scene);
  const double E0 = field.energy(scene.initial_positions(), scene.initial_velocities()).total();
  for (LinearSolverKind solver : {LinearSolverKind::ldlt, LinearSolverKind::cg}) {
    NewtonSettings newton;
    newton.solver = solver;
    if (solver == LinearSolverKind::cg) newton.treatment = StiffnessTreatment::definite;
    auto stepper = make_stepper("implicit_euler", field, {newton});
    Vector x = scene.initial_positions(), v = scene.initial_velocities();
    REQUIRE(stepper->step(0.01, x, v));  // one step: a 30000-unknown Newton solve per iteration
    CHECK(field.energy(x, v).total() <= E0 + 1e-9 * E0);
    CHECK(x.allFinite());
    CHECK(v.allFinite());
  }
}

TEST_CASE("a 60 s run: symplectic Euler's energy error stays bounded at D = 0; implicit Euler's never rises") {
  SceneParams p;
  p.grid.M = 6;
  p.grid.N = 6;
  p.stiffness = 50;
  const RunResult s = run(p, "symplectic_euler", 0.01, 60.0);
  REQUIRE(s.status == RunStatus::ok);
  const double E0 = s.energy.front().energy.total();
  double early = 0, late = 0;  // largest |E - E0| in the first and the last 10 s
  for (const EnergySample& e : s.energy) {
    const double err = std::abs(e.energy.total() - E0);
    if (e.t <= 10) early = std::max(early, err);
    if (e.t >= 50) late = std::max(late, err);
  }
  CHECK(late < 2 * early);  // no drift: the error oscillates within the same band after 60 s
  CHECK(late < 0.05 * E0);
  for (double D : {0.0, 20.0}) {
    p.damping = D;
    const RunResult r = run(p, "implicit_euler", 0.01, 60.0);
    REQUIRE(r.status == RunStatus::ok);
    CHECK(energy_never_rises(r, 1e-9 * r.energy.front().energy.total()));
  }
}
