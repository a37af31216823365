// The bending term inside the ForceField (Chapter 12), against independent truth: its forces against central
// differences of its energy, its df/dx against central differences of its forces, the Newton matrices against
// M - h^2 df/dx, and runs of registry methods with bending on an undamped sheet: their observed order (RK4 4,
// the explicit midpoint rule 2) and RK4's energy kept to 1e-8.
#include <doctest/doctest.h>

#include "integrators/method_registry.hpp"
#include "model/bending.hpp"
#include "random_state.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

using namespace cloth;
using cloth::testing::random_state;

namespace {

// A 5 x 4 sheet of Chapter 10's fabric scale (d = 5 cm, m = 6.25e-4 kg), one edge pinned so that some hinges
// touch pinned particles, with a bending term of rigidity B large enough to be seen beside the springs.
SceneParams bent_sheet(BendingModel model, double damping = 0) {
  SceneParams p;
  p.grid = Grid{5, 4, 0.05};
  p.mass = 6.25e-4;
  p.stiffness = 100;
  p.damping = damping;
  p.pins = PinSet::edge;
  p.bending = model;
  p.bending_rigidity = 1e-3;
  return p;
}

double potential(ForceField& field, const Vector& x) {
  const Energy e = field.energy(x, Vector::Zero(x.size()));
  return e.gravity + e.spring;
}

}  // namespace

TEST_CASE("the ForceField's forces with a bending term are minus the gradient of its energy") {
  for (const BendingModel model : {BendingModel::hinge, BendingModel::quadratic}) {
    const Scene scene(bent_sheet(model));
    ForceField field(scene);
    REQUIRE(field.bending() != nullptr);
    std::mt19937 rng(7);
    const auto s = random_state(scene, rng, 1.0, 0.3, 0.0);
    Vector f(scene.dof_count()), f_springs(scene.dof_count());
    field.forces(s.x, s.v, f);
    // The bending term is a real part of the force: without it, the forces differ by more than the check's error.
    SceneParams without = bent_sheet(model);
    without.bending = BendingModel::flexion;
    const Scene springs_scene(without);
    ForceField springs_only(springs_scene);
    springs_only.forces(s.x, s.v, f_springs);
    CHECK((f - f_springs).norm() > 1e-2 * f.norm());
    const double h = 1e-7;
    for (int k = 0; k < scene.dof_count(); ++k) {
      Vector xp = s.x, xm = s.x;
      xp[k] += h;
      xm[k] -= h;
      const double dE = (potential(field, xp) - potential(field, xm)) / (2 * h);
      CHECK(-dE == doctest::Approx(f[k]).epsilon(1e-6).scale(1e-3));
    }
  }
}

TEST_CASE("with a bending term, df/dx is the derivative of the forces and the Newton matrices hold h^2 of it") {
  for (const BendingModel model : {BendingModel::hinge, BendingModel::quadratic}) {
    const Scene scene(bent_sheet(model));
    ForceField field(scene);
    std::mt19937 rng(3);
    const auto s = random_state(scene, rng, 1.0, 0.3, 0.0);
    SparseMatrix dfdx = field.pattern(), dfdv = field.pattern(), A = field.pattern(), F = field.pattern();
    field.jacobians(s.x, s.v, dfdx, dfdv);
    const Eigen::MatrixXd J(dfdx);
    const int n = scene.dof_count();
    Vector fp(n), fm(n);
    const double h = 1e-6;
    for (int k = 0; k < n; ++k) {
      Vector xp = s.x, xm = s.x;
      xp[k] += h;
      xm[k] -= h;
      field.forces(xp, s.v, fp);
      field.forces(xm, s.v, fm);
      const Vector column = (fp - fm) / (2 * h);
      CHECK((J.col(k) - column).norm() <= 1e-6 * (1 + column.norm()));
    }
    // Undamped, every treatment but definite is M - h^2 df/dx exactly; the frozen form too.
    const double step = 0.01, m = scene.params().mass;
    const Eigen::MatrixXd expected = m * Eigen::MatrixXd::Identity(n, n) - step * step * J;
    field.newton_matrix(s.x, s.v, step, StiffnessTreatment::exact, A);
    CHECK((Eigen::MatrixXd(A) - expected).norm() <= 1e-12 * expected.norm());
    field.frozen_newton_matrix(s.x, step, StiffnessTreatment::symmetric, F);
    CHECK((Eigen::MatrixXd(F) - expected).norm() <= 1e-12 * expected.norm());
    // definite keeps a positive definite matrix even where the hinges' exact Hessian is not.
    field.newton_matrix(s.x, s.v, step, StiffnessTreatment::definite, A);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig{Eigen::MatrixXd(A)};
    CHECK(eig.eigenvalues().minCoeff() > 0);
  }
}

TEST_CASE("frozen_forces' elastic potential includes the bending energy, and its force is forces()'s") {
  const Scene scene(bent_sheet(BendingModel::hinge, 0.01));
  ForceField field(scene);
  std::mt19937 rng(5);
  const auto s = random_state(scene, rng, 1.0, 0.3, 0.0);  // v = 0: the frozen dampers exert nothing
  field.freeze_dampers(s.x);
  Vector f(scene.dof_count()), g(scene.dof_count());
  const ForceField::Potentials p = field.frozen_forces(s.x, s.v, f);
  field.forces(s.x, s.v, g);
  CHECK((f - g).norm() <= 1e-14 * g.norm());
  CHECK(p.spring == doctest::Approx(field.energy(s.x, s.v).spring).epsilon(1e-13));
  CHECK(p.spring > 0);
}

TEST_CASE("registry methods on an undamped sheet with bending: their observed order, and the energy kept") {
  // No gravity, the sheet pinned along one edge and released bent: bending and the springs drive the motion.
  for (const BendingModel model : {BendingModel::hinge, BendingModel::quadratic}) {
    SceneParams p = bent_sheet(model);
    p.gravity = 0;
    p.initial_velocity_z = 0;
    const Scene scene(p);
    ForceField field(scene);
    Vector x0 = scene.initial_positions();
    // The free rows lifted along a parabola: every hinge across the strip bends.
    for (int slot = 0; slot < scene.free_count(); ++slot) {
      const int j = scene.particle_of_slot(slot) % scene.grid().N;
      const double from_edge = (scene.grid().N - 1 - j) * scene.grid().d;
      x0[3 * slot + 2] = 2.0 * from_edge * from_edge;
    }
    const Vector v0 = Vector::Zero(scene.dof_count());
    const double E0 = field.energy(x0, v0).total(), T = 0.05;
    for (const auto& [name, order] : {std::pair{"rk4", 4}, std::pair{"midpoint", 2}}) {
      CAPTURE(name);
      Vector end[3];
      double drift = 0;
      for (int halving = 0; halving < 3; ++halving) {
        const double h = 1e-4 / (1 << halving);
        auto stepper = make_stepper(name, field);
        Vector x = x0, v = v0;
        for (int k = 0; k < static_cast<int>(std::lround(T / h)); ++k) REQUIRE(stepper->step(h, x, v));
        end[halving] = x;
        drift = std::abs(field.energy(x, v).total() - E0) / E0;
      }
      // The motion is real (the sheet moved by a good part of its lift), and the differences between successive
      // halvings fall by 2^p: the bending force enters the solution at the method's order.
      CHECK((end[2] - x0).lpNorm<Eigen::Infinity>() > 1e-3);
      const double ratio = (end[0] - end[1]).norm() / (end[1] - end[2]).norm(), expected = std::pow(2.0, order);
      CHECK(ratio > 0.8 * expected);
      CHECK(ratio < 1.25 * expected);
      // A force that were not minus the gradient of the energy would change it by O(1) however small h is.
      if (order == 4) CHECK(drift < 1e-8);
    }
  }
}

TEST_CASE("bending in XPBD and local/global: a bent sheet relaxes as implicit Euler's does, to first order in h") {
  // Both take the bending force explicitly, at the step's start (integrators/xpbd.cpp, local_global.cpp): each step
  // then differs from implicit Euler's by O(h^2), so at a fixed time T the gap to implicit Euler at the same h is
  // O(h) and halves with h, provided h is inside the explicit bending term's stability limit. The sheet of the
  // order test, released bent and damped, without gravity: bending alone drives the motion.
  SceneParams p = bent_sheet(BendingModel::hinge, 0.01);
  p.gravity = 0;
  p.initial_velocity_z = 0;
  const Scene scene(p);
  ForceField field(scene);
  Vector x0 = scene.initial_positions();
  for (int slot = 0; slot < scene.free_count(); ++slot) {
    const int j = scene.particle_of_slot(slot) % scene.grid().N;
    const double from_edge = (scene.grid().N - 1 - j) * scene.grid().d;
    x0[3 * slot + 2] = 2.0 * from_edge * from_edge;
  }
  const Vector v0 = Vector::Zero(scene.dof_count());
  const double E0 = field.energy(x0, v0).total(), T = 0.1;
  MethodSettings converged;
  converged.local_global_iterations = 200;
  converged.xpbd_iterations = 200;
  converged.newton.tolerance = 1e-12;
  const auto run = [&](const char* name, double h, double& energy) {
    auto stepper = make_stepper(name, field, converged);
    Vector x = x0, v = v0;
    for (int k = 0; k < static_cast<int>(std::lround(T / h)); ++k) REQUIRE(stepper->step(h, x, v));
    energy = field.energy(x, v).total();
    return x;
  };
  for (const char* name : {"local_global", "xpbd"}) {
    CAPTURE(name);
    double gap[2] = {0, 0}, motion = 0;
    for (int halving = 0; halving < 2; ++halving) {
      const double h = 2e-3 / (1 << halving);
      double E_reference = 0, E = 0;
      const Vector reference = run("implicit_euler", h, E_reference);
      const Vector x = run(name, h, E);
      gap[halving] = (x - reference).lpNorm<Eigen::Infinity>();
      motion = (reference - x0).lpNorm<Eigen::Infinity>();
      INFO("h = " << h << ": motion " << motion << " m, gap " << gap[halving] << " m, E/E0 " << E / E0
                  << " (implicit Euler " << E_reference / E0 << ")");
      CHECK(E < 0.9 * E0);  // the sheet lost energy, as implicit Euler's did
      CHECK(std::abs(E - E_reference) <= 0.1 * E0);
    }
    INFO("gaps " << gap[0] << ", " << gap[1] << " m against a motion of " << motion << " m");
    CHECK(motion > 1e-2);                // bending moved the sheet by a good part of its 2 cm lift
    CHECK(gap[1] <= 0.05 * motion);      // close to implicit Euler's sheet
    CHECK(gap[0] / gap[1] > 1.6);        // and closer as h halves: first order
    CHECK(gap[0] / gap[1] < 2.5);
  }
}

TEST_CASE("bending in the curtain, exact Jacobian: a zero pivot of LDL^T is met by the definite matrix, and counted") {
  // Chapter 12's curtain with the quadratic bending term (B = 5e-6 N m) after 66 steps of implicit Euler at
  // h = 0.01 s (tests/data/ch12_bending: final.dat of ch10_cloth at t = 0.66 s, every digit). At the next step the
  // exact Newton matrix M + h^2 H has a singular pivot block: the springs compressed in the folds make H
  // indefinite (their transverse stiffness K (1 - L0/l) is negative), and at this state one eigenvalue of
  // M + h^2 H crosses zero. The quadratic term's own Hessian is constant and semi-definite: it is not the cause.
  SceneParams p;
  p.grid = Grid{20, 20, 0.05};
  p.mass = 6.25e-4;
  p.stiffness = 1e5;
  p.damping = 0.01;
  p.initial_velocity_z = 0;
  p.pins = PinSet::edge;
  p.families.on[static_cast<int>(SpringFamily::flexion)] = false;
  p.bending = BendingModel::quadratic;
  p.bending_rigidity = 5e-6;
  const Scene scene(p);
  std::ifstream in(std::string(CLOTH_SOURCE_DIR) + "/tests/data/ch12_bending/drape_quadratic_step66.dat");
  REQUIRE(in);
  Vector x0 = scene.initial_positions(), v0 = scene.initial_velocities();
  std::string line;
  int read = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    int i = 0, j = 0;
    double q[6];
    fields >> i >> j >> q[0] >> q[1] >> q[2] >> q[3] >> q[4] >> q[5];
    REQUIRE(fields);
    ++read;
    const int s = scene.slot(scene.grid().particle(i, j));
    if (s >= scene.free_count()) continue;
    for (int c = 0; c < 3; ++c) {
      x0[3 * s + c] = q[c];
      v0[3 * s + c] = q[3 + c];
    }
  }
  REQUIRE(read == 400);
  const double h = 0.01;
  const auto step = [&](StiffnessTreatment treatment, Vector& x, Vector& v) {
    ForceField field(scene);
    MethodSettings settings;
    settings.newton.treatment = treatment;
    settings.newton.solver = LinearSolverKind::ldlt;
    settings.newton.tolerance = 1e-10;
    const auto stepper = make_stepper("implicit_euler", field, settings);
    x = x0;
    v = v0;
    const bool ok = stepper->step(h, x, v);
    INFO(stepper->failure().reason);
    REQUIRE(ok);
    return stepper->counters().definite_fallbacks;
  };
  Vector x_exact, v_exact, x_definite, v_definite;
  const long long fallbacks = step(StiffnessTreatment::exact, x_exact, v_exact);
  CHECK(step(StiffnessTreatment::definite, x_definite, v_definite) == 0);
  // The exact matrix failed at least once and the step still reached implicit Euler's step: both treatments
  // converge to the same stage, whatever matrix the iterations used.
  CHECK(fallbacks >= 1);
  const double motion = (x_exact - x0).lpNorm<Eigen::Infinity>();
  CHECK(motion > 1e-3);
  CHECK((x_exact - x_definite).lpNorm<Eigen::Infinity>() <= 1e-7 * motion);
}
