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
#include <random>

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
  // order test, damped, without gravity, released rolled onto a cylinder of radius 0.15 m about its pinned edge:
  // an isometry but for the chords, so bending holds a fifth of the energy and drives the motion (the springs' share
  // is their chords' compression).
  SceneParams p = bent_sheet(BendingModel::hinge, 0.01);
  p.gravity = 0;
  p.initial_velocity_z = 0;
  const Scene scene(p);
  ForceField field(scene);
  Vector x0 = scene.initial_positions();
  const double R = 0.15, edge_y = (scene.grid().N - 1) * scene.grid().d;
  for (int slot = 0; slot < scene.free_count(); ++slot) {
    const int j = scene.particle_of_slot(slot) % scene.grid().N;
    const double s = edge_y - j * scene.grid().d;  // arc length from the pinned edge
    x0[3 * slot + 1] = edge_y - R * std::sin(s / R);
    x0[3 * slot + 2] = R * (1 - std::cos(s / R));
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
      const double h = 4e-4 / (1 << halving);
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
    CHECK(motion > 1e-2);                // the sheet moved (by 2 cm): the gaps are small against something
    CHECK(gap[1] <= 0.01 * motion);      // close to implicit Euler's sheet
    CHECK(gap[0] / gap[1] > 1.6);        // and closer as h halves: first order
    CHECK(gap[0] / gap[1] < 2.5);
  }
}

TEST_CASE("bending in the curtain, exact Newton matrix: the zero pivot at step 67 is met by the definite matrix") {
  // Chapter 12's curtain (20 x 20, d = 5 cm, K = 1e5 N/m, D = 0.01, top edge pinned, released flat) with the
  // quadratic term of B = 5e-6 N m, by implicit Euler at h = 0.01 s with the exact Newton matrix and LDL^T. At
  // step 67 a pivot block of M + h^2 H is singular: the springs compressed in the folds make H indefinite (their
  // transverse stiffness K (1 - L0/l) is negative); the quadratic term's own Hessian is constant and semi-definite.
  // Without the fallback that step failed (`ch10_cloth --grid 20x20 --spacing 0.05 --mass 6.25e-4 --K 1e5
  // --damping 0.01 --pins edge --v0 0 --springs structural,shear --bending quadratic --bending-rigidity 5e-6
  // --method implicit_euler --dt 0.01 --jacobian exact --linear-solver ldlt` stopped there, exit 3); now the
  // iteration takes the definite matrix, counts it, and every step converges.
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
  ForceField field(scene);
  MethodSettings settings;
  settings.newton.treatment = StiffnessTreatment::exact;
  settings.newton.solver = LinearSolverKind::ldlt;
  const auto stepper = make_stepper("implicit_euler", field, settings);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  long long before = 0;
  for (int step = 1; step <= 68; ++step) {
    CAPTURE(step);
    const bool ok = stepper->step(0.01, x, v);
    INFO(stepper->failure().reason);
    REQUIRE(ok);
    if (step == 66) before = stepper->counters().definite_fallbacks;
  }
  CHECK(stepper->counters().definite_fallbacks > before);  // step 67 (or 68) needed the definite matrix
  CHECK(x.allFinite());
}
