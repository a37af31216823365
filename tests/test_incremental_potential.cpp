// The implicit stage as the minimisation of the incremental potential (Chapter 4): Phi's gradient is the stage
// residual, Newton with the backtracking search on Phi decreases it at every iteration and takes the frame step
// from the flat curtain that the residual search cannot, and freezing the dampers changes the motion by O(h).
#include "integrators/block_ldu.hpp"
#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"

#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
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

namespace {

// Chapter 10's fabric curtain at 20 x 20 and K = 1e6 (the map's part curtain_20_1e6): 0.95 m square, 0.25 kg/m^2,
// flexion springs as stiff as the others, hung by one edge and released flat.
SceneParams stiff_fabric_curtain() {
  SceneParams p = curtain();
  p.grid.d = 0.05;
  p.mass = 0.25 * p.grid.d * p.grid.d;
  p.stiffness = 1e6;
  return p;
}

// The largest transverse stiffness |T| / l that a compressed spring of state x (free slots) contributes to -df/dx
// with a negative sign: the term the definite matrix drops.
double largest_compressed_transverse_stiffness(const Scene& scene, const Vector& x) {
  Vector all = scene.rest_positions();
  all.head(x.size()) = x;
  double largest = 0;
  for (int f = 0; f < 3; ++f) {
    const SpringRange range = scene.springs().family[static_cast<std::size_t>(f)];
    for (int i = range.begin; i < range.end; ++i) {
      const Spring& s = scene.springs().springs[static_cast<std::size_t>(i)];
      const double l = (all.segment<3>(3 * s.p) - all.segment<3>(3 * s.q)).norm();
      if (l < s.rest_length)
        largest = std::max(largest, scene.stiffness(static_cast<SpringFamily>(f)) * (s.rest_length - l) / l);
    }
  }
  return largest;
}

}  // namespace

TEST_CASE("definite Newton descends on Phi but contracts only linearly where compressed springs outweigh M / h^2") {
  const Scene scene(stiff_fabric_curtain());
  ForceField field(scene);
  const double h = 1.0 / 30, m = scene.params().mass;
  const Vector x0 = scene.initial_positions(), v0 = scene.initial_velocities();
  NewtonSettings exact;
  exact.tolerance = 1e-6;
  ImplicitEuler exact_step(field, exact);
  Vector x = x0, v = v0;
  REQUIRE(exact_step.step(h, x, v));
  const std::vector<double>& exact_updates = exact_step.newton().update_history();
  REQUIRE(exact_updates.size() >= 3);
  // Exact Newton ends quadratically: its last update is far below the one before.
  CHECK(exact_updates.back() < 0.1 * exact_updates[exact_updates.size() - 2]);
  // At the stage solution compressed springs carry a negative transverse stiffness many times the inertia m / h^2
  // (about 70 times here): the definite matrix, which drops it, overestimates the Hessian in those directions.
  const double dropped = largest_compressed_transverse_stiffness(scene, x);
  INFO("largest compressed |T|/l " << dropped << " N/m against m/h^2 = " << m / (h * h) << " N/m");
  CHECK(dropped > 10 * m / (h * h));

  // Halfway to the solution the definite update is a descent direction of the Phi the search uses: its slope
  // along dv by central differences is r . dv < 0 (the frozen dampers make damping a gradient).
  StepCounters counters;
  StageNewton newton(field, exact, counters);
  const Vector V = 0.5 * v;
  const double phi = newton.potential(x0, v0, h, V);  // also freezes the dampers at x0 + h v0
  REQUIRE(std::isfinite(phi));
  const Vector r = frozen_residual(field, x0, v0, h, V);
  SparseMatrix A = field.pattern();
  field.frozen_newton_matrix(x0 + h * V, h, StiffnessTreatment::definite, A);
  const Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);
  REQUIRE(ldlt.info() == Eigen::Success);
  const Vector dv = ldlt.solve(-r);
  // The block LDL^T's inertia test against dense eigenvalues, for the definite matrix and the exact one here.
  for (StiffnessTreatment treatment : {StiffnessTreatment::definite, StiffnessTreatment::exact}) {
    SparseMatrix B = field.pattern();
    field.frozen_newton_matrix(x0 + h * V, h, treatment, B);
    BlockLDU block;
    block.analyze(B, BlockLDU::Symmetry::symmetric);
    REQUIRE(block.factorize(B));
    const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(B), Eigen::EigenvaluesOnly)
                              .eigenvalues()
                              .minCoeff();
    INFO((treatment == StiffnessTreatment::definite ? "definite" : "exact") << ": lowest eigenvalue " << lowest);
    CHECK(block.positive_definite() == (lowest > 0));
  }
  const double eps = 1e-7 / dv.lpNorm<Eigen::Infinity>();
  const double slope = (newton.potential(x0, v0, h, V + eps * dv) - newton.potential(x0, v0, h, V - eps * dv)) /
                       (2 * eps);
  INFO("slope of Phi along the definite update: " << slope << ", r . dv " << r.dot(dv));
  CHECK(r.dot(dv) < 0);
  CHECK(slope == doctest::Approx(r.dot(dv)).epsilon(1e-4));

  // So the definite iteration takes its full updates and still converges only linearly, at a rate near 1.
  NewtonSettings definite = exact;
  definite.treatment = StiffnessTreatment::definite;
  ImplicitEuler definite_step(field, definite);
  Vector xd = x0, vd = v0;
  REQUIRE(definite_step.step(h, xd, vd));
  const std::vector<double>& updates = definite_step.newton().update_history();
  const std::vector<double>& fractions = definite_step.newton().step_fractions();
  REQUIRE(updates.size() > exact_updates.size() + 10);
  for (std::size_t k = updates.size() - 10; k < updates.size(); ++k) {
    INFO("definite iteration " << k << ": fraction " << fractions[k] << ", |dv| " << updates[k - 1] << " -> "
                               << updates[k]);
    CHECK(fractions[k] == 1.0);
    CHECK(updates[k] / updates[k - 1] > 0.6);
    CHECK(updates[k] / updates[k - 1] < 0.95);
  }
  // Both converged to the same stage solution, within the tolerance's reach.
  CHECK((vd - v).lpNorm<Eigen::Infinity>() < 1e-4);
}
