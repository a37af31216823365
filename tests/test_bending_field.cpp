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
