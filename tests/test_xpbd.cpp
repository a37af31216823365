// XPBD and small steps (Chapter 10): one projection meets its constraint's compliance equation exactly, the
// projections conserve momentum, converged XPBD differs from implicit Euler's step by the gap its dropped term
// predicts, and small steps converge at first order in the substep.
#include <doctest/doctest.h>

#include "analysis/spring_strain.hpp"
#include "base/input_error.hpp"
#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/symplectic_euler.hpp"
#include "integrators/xpbd.hpp"
#include "light_cloth.hpp"

#include <Eigen/Geometry>
#include <Eigen/SparseLU>
#include <cmath>

using namespace cloth;
using cloth::testing::light_cloth;
using cloth::testing::moving_state;
using cloth::testing::State;

namespace {

// The total momentum m sum v of the free particles.
Eigen::Vector3d momentum(const Vector& v, double m) { return m * v.reshaped(3, v.size() / 3).rowwise().sum(); }

}  // namespace

TEST_CASE("one projection of a distance constraint meets its compliance equation C + alpha~ lambda = 0 exactly") {
  const Eigen::Vector3d p0(0.3, -0.1, 0.2), q0(-0.05, 0.4, 0.1);
  const double L0 = 0.25;
  const double l0 = (p0 - q0).norm();
  REQUIRE(std::abs(l0 - L0) > 0.2);  // far from satisfied to start with
  struct Case {
    double w_p, w_q, alpha_tilde;
  };
  for (const Case c : {Case{2.0, 2.0, 0.0}, Case{3.0, 0.0, 0.0}, Case{2.0, 5.0, 0.7}}) {
    CAPTURE(c.w_p);
    CAPTURE(c.alpha_tilde);
    Eigen::Vector3d p = p0, q = q0;
    double lambda = 0;
    const double dlambda = project_distance_constraint(p, q, p0, q0, c.w_p, c.w_q, L0, c.alpha_tilde, 0.0, lambda);
    CHECK(lambda == dlambda);
    const double C = (p - q).norm() - L0;
    // Compliance 0 is PBD's hard constraint: met to rounding after one projection. Otherwise C = -alpha~ lambda.
    CHECK(std::abs(C + c.alpha_tilde * lambda) <= 1e-15);
    if (c.alpha_tilde > 0) CHECK(std::abs(C) > 0.01);
    // The correction is along the spring and weighted by inverse mass: a pinned end (w = 0) does not move, and
    // the mass-weighted centre p / w_p + q / w_q stays where it was.
    CHECK(((p - p0).cross(p0 - q0)).norm() <= 1e-15);
    if (c.w_q == 0) CHECK(q == q0);
    else CHECK(((p / c.w_p + q / c.w_q) - (p0 / c.w_p + q0 / c.w_q)).norm() <= 1e-15);
  }
}

TEST_CASE("XPBD and small steps conserve the linear momentum of a free cloth without gravity, damped or not") {
  for (const double D : {0.0, 0.02}) {
    SceneParams p = light_cloth(D);
    p.pins = PinSet::none;
    p.gravity = 0;
    const Scene scene(p);
    ForceField field(scene);
    // A stretched, tumbling start: every particle displaced and moving in its own way.
    Vector x = scene.initial_positions(), v = scene.initial_velocities();
    for (Eigen::Index k = 0; k < x.size(); ++k) {
      x[k] *= 1.1 + 0.02 * std::sin(3.0 * static_cast<double>(k));
      v[k] = std::cos(1.7 * static_cast<double>(k)) + (k % 3 == 0 ? 1.0 : 0.0);  // drifting along x
    }
    const Eigen::Vector3d P0 = momentum(v, p.mass);
    REQUIRE(P0.norm() > 1e-3);
    for (const char* name : {"xpbd", "small_steps"}) {
      CAPTURE(name);
      MethodSettings settings;
      settings.substeps = 3;
      const auto stepper = make_stepper(name, field, settings);
      Vector xs = x, vs = v;
      for (int k = 0; k < 20; ++k) REQUIRE(stepper->step(1.0 / 60, xs, vs));
      CHECK((xs - x).cwiseAbs().maxCoeff() > 0.1);  // the cloth moved
      CHECK((momentum(vs, p.mass) - P0).norm() <= 1e-13 * (P0.norm() + p.mass * vs.cwiseAbs().sum()));
    }
  }
}

TEST_CASE("converged XPBD is implicit Euler's step up to A^-1 r, r implicit Euler's residual at XPBD's answer") {
  // Macklin et al. (2016) drop the momentum residual g from their Newton step, so the fixed point of many
  // XPBD iterations meets every compliance equation but leaves r = M (x - x~) - h^2 f(x, (x - x0)/h) (the
  // springs' turning during the iteration times their multipliers; integrators/xpbd.cpp). Then x_xpbd - x_ie
  // = A^-1 r to first order, A = M - h df/dv - h^2 df/dx: the test checks that prediction to 5 %, which fails
  // whether the gap were zero (XPBD were Newton), larger, or of another shape.
  for (const double D : {0.0, 0.01}) {
    for (const double h : {1e-3, 4e-3}) {
      CAPTURE(D);
      CAPTURE(h);
      const Scene scene(light_cloth(D));
      const State s = moving_state(scene);
      ForceField field(scene);
      NewtonSettings tight;
      tight.tolerance = 1e-12;
      ImplicitEuler newton(field, tight);
      Vector x_ie = s.x, v_ie = s.v;
      REQUIRE(newton.step(h, x_ie, v_ie));

      MethodSettings many;
      many.xpbd_iterations = 2000;
      const auto xpbd = make_stepper("xpbd", field, many);
      Vector x = s.x, v = s.v;
      REQUIRE(xpbd->step(h, x, v));
      many.xpbd_iterations = 4000;  // converged: twice the iterations change nothing that matters here
      Vector x2 = s.x, v2 = s.v;
      REQUIRE(make_stepper("xpbd", field, many)->step(h, x2, v2));

      // r = M (x - x0 - h v0) - h^2 f(x, v), and the predicted gap A^-1 r.
      Vector f(x.size());
      field.forces(x, v, f);
      const Vector r = scene.params().mass * (x - s.x - h * s.v) - h * h * f;
      SparseMatrix A = field.pattern();
      field.newton_matrix(x, v, h, StiffnessTreatment::exact, A);
      Eigen::SparseLU<SparseMatrix> lu(A);
      REQUIRE(lu.info() == Eigen::Success);
      const Vector predicted = lu.solve(r);

      const double gap = (x - x_ie).cwiseAbs().maxCoeff();
      const double motion = (x_ie - s.x).cwiseAbs().maxCoeff();
      INFO("h = " << h << ", D = " << D << ": step " << motion << " m, XPBD - implicit Euler " << gap
                     << " m, predicted " << predicted.cwiseAbs().maxCoeff() << " m, unconverged "
                     << (x2 - x).cwiseAbs().maxCoeff() << " m");
      CHECK(motion > 1e-4);
      CHECK((x2 - x).cwiseAbs().maxCoeff() < 1e-3 * gap);
      CHECK(gap > 1e-6 * motion);  // there is a gap: XPBD's fixed point is not implicit Euler's step
      CHECK((x - x_ie - predicted).cwiseAbs().maxCoeff() <= 0.05 * gap);
    }
  }
}

TEST_CASE("small steps converge at first order in the substep to the true motion of a small cloth") {
  SceneParams p;
  p.grid = Grid{4, 4, 0.1};
  p.stiffness = 50;
  p.damping = 0.5;
  p.initial_velocity_z = -1;
  const Scene scene(p);
  ForceField field(scene);
  const double T = 0.2, h = 0.02;
  // The reference: RK4 at a step far below the one the substeps reach (its error ~ 1e-12 m).
  const auto rk4 = make_stepper("rk4", field);
  Vector x_ref = scene.initial_positions(), v_ref = scene.initial_velocities();
  for (int k = 0; k < 20000; ++k) rk4->step(T / 20000, x_ref, v_ref);
  double previous = 0, order = 0;
  for (const int n : {8, 16, 32, 64}) {
    MethodSettings settings;
    settings.substeps = n;
    const auto stepper = make_stepper("small_steps", field, settings);
    Vector x = scene.initial_positions(), v = scene.initial_velocities();
    for (int k = 0; k < std::lround(T / h); ++k) REQUIRE(stepper->step(h, x, v));
    const double error = (x - x_ref).cwiseAbs().maxCoeff();
    CAPTURE(n);
    CAPTURE(error);
    if (previous > 0) {
      order = std::log2(previous / error);
      CHECK(order == doctest::Approx(1.0).epsilon(0.15));
    }
    previous = error;
  }
  CHECK(previous > 1e-6);  // above the reference's error, so the order is the method's
}

TEST_CASE("the registry's position-based rows take their settings, and refuse the report's damping law") {
  const Scene scene(light_cloth(0.01));
  ForceField field(scene);
  MethodSettings settings;
  settings.xpbd_iterations = 7;
  settings.substeps = 3;
  const auto xpbd = make_stepper("xpbd", field, settings);
  const auto& x = dynamic_cast<const Xpbd&>(*xpbd);
  CHECK(x.iterations() == 7);
  CHECK(x.substeps() == 3);
  const auto small = make_stepper("small_steps", field, settings);
  CHECK(dynamic_cast<const Xpbd&>(*small).iterations() == 1);
  CHECK(dynamic_cast<const Xpbd&>(*small).substeps() == 3);
  CHECK(dynamic_cast<const Xpbd&>(*make_stepper("small_steps", field)).substeps() == 20);
  CHECK(dynamic_cast<const Xpbd&>(*make_stepper("xpbd", field)).substeps() == 1);
  CHECK(find_method("xpbd").family == MethodFamily::position_based);
  CHECK(std::string(method_families().name(MethodFamily::position_based)) == "position_based");
  SceneParams report = light_cloth(0.01);
  report.damping_model = DampingModel::report;
  const Scene report_scene(report);
  ForceField report_field(report_scene);
  CHECK_THROWS_AS(make_stepper("xpbd", report_field), InputError);
  CHECK_THROWS_AS(Xpbd(field, "xpbd", 0, 1), InputError);
}

TEST_CASE("the largest spring strain: zero at rest, and the stretch of the one spring a hand-made state stretches") {
  SceneParams p = light_cloth(0.0);
  p.pins = PinSet::corners;
  const Scene scene(p);
  Vector all(3 * scene.particle_count());
  scene.all_positions(scene.initial_positions(), all);
  CHECK(std::abs(largest_spring_strain(scene, all)) <= 1e-15);
  // Particle (0, 0) is pinned; moving its neighbour (1, 0) away along x by 10 % of the spacing stretches the
  // structural spring between them by 10 %, and every other spring of (1, 0) by less (they are not along x, or
  // are longer: the flexion spring (1, 0)-(3, 0) is compressed).
  const int k = scene.grid().particle(1, 0);
  all[3 * k] += 0.1 * p.grid.d;
  CHECK(largest_spring_strain(scene, all) == doctest::Approx(0.1).epsilon(1e-12));
  // Squeezing the whole sheet to 90 % leaves every spring compressed by 10 %: the largest strain is -0.1.
  scene.all_positions(scene.initial_positions(), all);
  all *= 0.9;
  CHECK(largest_spring_strain(scene, all) == doctest::Approx(-0.1).epsilon(1e-12));
}
