// The implicit stage as the minimisation of the incremental potential (Chapter 4): Phi's gradient is the stage
// residual, Newton with the backtracking search on Phi decreases it at every iteration and takes the frame step
// from the flat curtain that the residual search cannot, and freezing the dampers changes the motion by O(h).
#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"

#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

using namespace cloth;

namespace {

// Chapter 4's curtain: 20 x 20 particles 5 cm apart hung by one edge, released flat and at rest.
SceneParams curtain() {
  SceneParams p;
  p.grid.d = 0.05;
  p.mass = 6.25e-4;
  p.stiffness = 1e5;
  p.damping = 0.01;
  p.initial_velocity_z = 0;
  p.pins = PinSet::edge;
  return p;
}

Vector random_vector(int n, double scale, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Vector r(n);
  for (int i = 0; i < n; ++i) r[i] = u(rng);
  return r;
}

// r(V) = M (V - v~) - gamma f(x~ + gamma V, V) with the dampers frozen at the free-flight position x~ + gamma v~,
// computed here from the force field.
Vector frozen_residual(ForceField& field, const Vector& x_tilde, const Vector& v_tilde, double gamma, const Vector& V) {
  field.freeze_dampers(x_tilde + gamma * v_tilde);
  Vector f(field.dof_count());
  const Vector x = x_tilde + gamma * V;
  field.frozen_forces(x, V, f);
  return field.scene().params().mass * (V - v_tilde) - gamma * f;
}

}  // namespace

TEST_CASE("minimising Newton decreases Phi at every iteration and takes the 1/30 s step from the flat curtain") {
  const Scene scene(curtain());
  ForceField field(scene);
  const double h = 1.0 / 30;
  const Vector x0 = scene.initial_positions(), v0 = scene.initial_velocities();
  ImplicitEuler minimising(field, NewtonSettings{});
  Vector x = x0, v = v0;
  REQUIRE(minimising.step(h, x, v));
  const StageNewton& newton = minimising.newton();
  const std::vector<double>& phi = newton.potential_history();
  const std::vector<double>& r = newton.residual_history();
  REQUIRE(phi.size() == r.size());
  REQUIRE(phi.size() >= 5);  // from flat the model has no transverse stiffness: many iterations, not one
  // Every accepted update lowers Phi, until its last iterations, where Phi's change is below the rounding of its
  // sums (|Phi| ~ 1e-2 J here, 1e-13 J of rounding at most) and the residual judges.
  for (std::size_t k = 0; k + 1 < phi.size(); ++k) {
    INFO("iteration " << k << ": Phi " << phi[k] << " -> " << phi[k + 1] << ", |r| " << r[k] << " -> " << r[k + 1]);
    CHECK(phi[k + 1] <= phi[k] + 1e-13);
  }
  CHECK(phi.back() < phi.front() - 1e-3);  // the frame step lowers Phi by about 1.2e-2 J from the flat sheet
  // Converged by Chapter 4's rule: |r|_inf <= 1e-8 m (1 + |V|_inf).
  CHECK(r.back() <= 1e-8 * scene.params().mass * (1 + v.lpNorm<Eigen::Infinity>()));
  // The velocities solve the frozen stage equation, checked from the forces directly.
  CHECK(frozen_residual(field, x0, v0, h, v).lpNorm<Eigen::Infinity>() <= 1e-8 * scene.params().mass * (1 + v.lpNorm<Eigen::Infinity>()));
  // The sheet fell: the step moved it by centimetres, not by nothing.
  CHECK((x - x0).lpNorm<Eigen::Infinity>() > 1e-3);

  // The same step with the search on the residual: its 1/64 floor keeps it crawling, and it fails.
  NewtonSettings residual;
  residual.line_search = LineSearch::residual;
  ImplicitEuler residual_form(field, residual);
  Vector xr = x0, vr = v0;
  CHECK_FALSE(residual_form.step(h, xr, vr));
  CHECK(xr == x0);
}

TEST_CASE("the gradient of Phi is the stage residual (central differences, damped curtain, both damping laws)") {
  for (DampingModel model : {DampingModel::projected, DampingModel::report}) {
    SceneParams p = curtain();
    p.grid.M = p.grid.N = 6;
    p.damping = 0.5;  // large enough that the dissipation potential's gradient is a visible part of r
    p.damping_model = model;
    const Scene scene(p);
    ForceField field(scene);
    NewtonSettings settings;
    settings.treatment = StiffnessTreatment::definite;
    StepCounters counters;
    StageNewton newton(field, settings, counters);
    std::mt19937 rng(7);
    const int n = field.dof_count();
    const double gamma = 0.01;
    const Vector x_tilde = scene.initial_positions() + random_vector(n, 0.01, rng);
    const Vector v_tilde = random_vector(n, 0.5, rng);
    const Vector V = random_vector(n, 0.5, rng);
    const Vector r = frozen_residual(field, x_tilde, v_tilde, gamma, V);
    for (int trial = 0; trial < 5; ++trial) {
      const Vector e = random_vector(n, 1.0, rng).normalized();
      const double eps = 1e-6;
      const double dphi = (newton.potential(x_tilde, v_tilde, gamma, V + eps * e) -
                           newton.potential(x_tilde, v_tilde, gamma, V - eps * e)) /
                          (2 * eps);
      INFO("damping model " << damping_model_name(model) << ", direction " << trial << ": dPhi/de " << dphi
                            << ", r.e " << r.dot(e));
      CHECK(dphi == doctest::Approx(r.dot(e)).epsilon(1e-6));
    }
  }
}

TEST_CASE("without damping the stage solution is a stationary point of Phi, and the definite matrix is SPD there") {
  SceneParams p = curtain();
  p.grid.M = p.grid.N = 8;
  p.damping = 0;
  const Scene scene(p);
  ForceField field(scene);
  const double h = 1e-3;
  const Vector x0 = scene.initial_positions(), v0 = scene.initial_velocities();
  // The stage solved by the other form (the residual search), which never evaluates Phi.
  NewtonSettings residual;
  residual.line_search = LineSearch::residual;
  residual.tolerance = 1e-10;
  ImplicitEuler stepper(field, residual);
  Vector x = x0, v = v0;
  const bool solved = stepper.step(h, x, v);
  INFO(stepper.failure().reason);
  REQUIRE(solved);
  StepCounters counters;
  StageNewton newton(field, NewtonSettings{}, counters);
  const int n = field.dof_count();
  std::mt19937 rng(11);
  // Phi's slope along random directions: zero at the solution, against the slope at the flat start.
  for (int trial = 0; trial < 4; ++trial) {
    const Vector e = random_vector(n, 1.0, rng).normalized();
    const double eps = 1e-5;
    const auto slope = [&](const Vector& V) {
      return (newton.potential(x0, v0, h, V + eps * e) - newton.potential(x0, v0, h, V - eps * e)) / (2 * eps);
    };
    INFO("direction " << trial << ": slope at the solution " << slope(v) << ", at the start " << slope(v0));
    CHECK(std::abs(slope(v)) <= 1e-6 * std::abs(slope(v0)) + 1e-12);
  }
  SparseMatrix A = field.pattern();
  field.frozen_newton_matrix(x, h, StiffnessTreatment::definite, A);
  const Eigen::MatrixXd dense(A);
  CHECK((dense - dense.transpose()).cwiseAbs().maxCoeff() == 0.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(dense);
  // The smallest eigenvalue is at least the mass: the definite spring blocks are positive semidefinite.
  CHECK(eigen.eigenvalues().minCoeff() >= p.mass * (1 - 1e-12));
}

TEST_CASE("freezing the dampers at the free-flight position changes the motion by O(h^2): observed orders") {
  // The frozen direction is taken at x~ + gamma v~, O(h^2) from the stage's position: the step changes by O(h^3)
  // and the motion at T by O(h^2), so implicit Euler barely moves, and the second-order methods keep their order.
  SceneParams p;  // the report scene's damped case, small: (K, D) = (200, 20) on 8 x 8
  p.grid.M = p.grid.N = 8;
  p.stiffness = 200;
  p.damping = 20;
  const Scene scene(p);
  ForceField field(scene);
  NewtonSettings frozen, current;
  frozen.tolerance = current.tolerance = 1e-12;
  current.line_search = LineSearch::residual;
  RunSettings run;
  run.t_end = 0.2;
  const auto final_positions = [&](const char* method, const NewtonSettings& s, double h) {
    const auto stepper = make_newton_stepper(method, field, {s});
    run.dt = h;
    const RunResult r = simulate(*stepper, run, false);
    REQUIRE(r.status == RunStatus::ok);
    return r.x;
  };
  // (At h = 0.01 the order is still 1.2, pre-asymptotic: h D / m = 0.2.)
  const double steps[3] = {0.005, 0.0025, 0.00125};
  double difference[3];
  for (int k = 0; k < 3; ++k)
    difference[k] = (final_positions("implicit_euler", frozen, steps[k]) -
                     final_positions("implicit_euler", current, steps[k])).lpNorm<Eigen::Infinity>();
  for (int k = 0; k + 1 < 3; ++k) {
    const double order = std::log2(difference[k] / difference[k + 1]);
    INFO("implicit Euler, h = " << steps[k] << ": frozen against current dampers " << difference[k] << " m, order " << order);
    CHECK(order > 1.6);  // with the dampers frozen at x~ instead it is 1.0: an O(h) change
    CHECK(order < 2.4);
  }
  // sdirk2 with frozen dampers converges at second order to the current-direction solution at a small step.
  const double sdirk2_steps[3] = {0.01, 0.005, 0.0025};
  const Vector reference = final_positions("sdirk2", current, sdirk2_steps[2] / 4);
  double error[3];
  for (int k = 0; k < 3; ++k)
    error[k] = (final_positions("sdirk2", frozen, sdirk2_steps[k]) - reference).lpNorm<Eigen::Infinity>();
  for (int k = 0; k + 1 < 3; ++k) {
    const double order = std::log2(error[k] / error[k + 1]);
    INFO("sdirk2, h = " << sdirk2_steps[k] << ": error " << error[k] << " m, order " << order);
    CHECK(order > 1.8);
  }
}
