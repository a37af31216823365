// Scenes against their definition in docs/model.md: which particles each pin set holds, that pinned particles are
// not unknowns and never move during a run, and that a free cloth's centre of mass falls exactly as the
// integrator says a single particle would (internal forces cancel).
#include <doctest/doctest.h>

#include "model/force_field.hpp"
#include "base/input_error.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "model/report_cases.hpp"

#include <Eigen/Geometry>
#include <memory>
#include <random>
#include <set>

using namespace cloth;

namespace {

// docs/model.md's pin sets, written out independently of the library.
bool pinned_by_definition(PinSet pins, int M, int N, int i, int j) {
  switch (pins) {
    case PinSet::corners: return (i == 0 || i == M - 1) && (j == 0 || j == N - 1);
    case PinSet::corner: return i == 0 && j == 0;
    case PinSet::edge: return j == N - 1;
    case PinSet::none: return false;
    case PinSet::clamped: return i <= 1;
  }
  return false;
}

constexpr PinSet all_pin_sets[] = {PinSet::corners, PinSet::corner, PinSet::edge, PinSet::none};

SceneParams params(int M, int N, PinSet pins) {
  SceneParams p;
  p.grid = Grid{M, N, 0.1};
  p.pins = pins;
  return p;
}

}  // namespace

TEST_CASE("pinned particles are not unknowns: dof = 3 (M N - pinned) and free particles take the first slots") {
  struct Size {
    int M, N, corners, corner, edge;  // pinned counts by hand
  };
  const Size sizes[] = {{20, 20, 4, 1, 20}, {3, 4, 4, 1, 3}, {2, 5, 4, 1, 2}, {6, 3, 4, 1, 6}};
  for (const Size& z : sizes) {
    for (PinSet pins : all_pin_sets) {
      CAPTURE(z.M);
      CAPTURE(z.N);
      CAPTURE(pin_set_name(pins));
      const Scene scene(params(z.M, z.N, pins));
      const int expected_pinned = pins == PinSet::corners ? z.corners
                                  : pins == PinSet::corner ? z.corner
                                  : pins == PinSet::edge   ? z.edge
                                                           : 0;
      CHECK(scene.dof_count() == 3 * (z.M * z.N - expected_pinned));
      CHECK(scene.free_count() == z.M * z.N - expected_pinned);
      std::set<int> slots;
      for (int i = 0; i < z.M; ++i)
        for (int j = 0; j < z.N; ++j) {
          const int particle = scene.grid().particle(i, j);
          const int slot = scene.slot(particle);
          const bool pinned = pinned_by_definition(pins, z.M, z.N, i, j);
          CHECK(scene.is_pinned(particle) == pinned);
          CHECK((slot < scene.free_count()) == !pinned);
          CHECK(scene.particle_of_slot(slot) == particle);
          slots.insert(slot);
        }
      CHECK(static_cast<int>(slots.size()) == z.M * z.N);  // a one-to-one numbering
      CHECK(*slots.begin() == 0);
      CHECK(*slots.rbegin() == z.M * z.N - 1);
      // The initial state: free particles at rest positions, moving with (0, 0, v0).
      const Vector v = scene.initial_velocities();
      for (int s = 0; s < scene.free_count(); ++s) {
        CHECK(v[3 * s] == 0.0);
        CHECK(v[3 * s + 2] == -20.0);
      }
    }
  }
}

TEST_CASE("pin sets that leave nothing free are refused") {
  CHECK_THROWS_AS(Scene(params(2, 2, PinSet::corners)), InputError);
  CHECK_NOTHROW(Scene(params(2, 3, PinSet::corners)));
}

TEST_CASE("pinned particles never move during a run, for every pin set and both explicit steppers") {
  for (PinSet pins : all_pin_sets) {
    for (bool symplectic : {false, true}) {
      CAPTURE(pin_set_name(pins));
      CAPTURE(symplectic);
      SceneParams p = params(6, 5, pins);
      p.damping = 2.0;
      const Scene scene(p);
      ForceField field(scene);
      const auto stepper = make_stepper(symplectic ? "symplectic_euler" : "explicit_euler", field);
      RunSettings run;
      run.dt = 0.002;
      run.t_end = 0.2;
      const RunResult result = simulate(*stepper, run, false);
      REQUIRE(result.status == RunStatus::ok);
      CHECK(result.steps == 100);

      Vector all(3 * scene.particle_count());
      scene.all_positions(result.x, all);
      const Grid& g = scene.grid();
      for (int i = 0; i < g.M; ++i)
        for (int j = 0; j < g.N; ++j) {
          const Eigen::Vector3d at = all.segment<3>(3 * g.particle(i, j));
          if (pinned_by_definition(pins, g.M, g.N, i, j))
            CHECK((at - g.rest_position(i, j)).cwiseAbs().maxCoeff() == 0.0);  // bit for bit
          else CHECK(at.z() < -0.5);  // launched at 20 m/s downwards: far below the plane after 0.2 s
        }
    }
  }
}

TEST_CASE("a free cloth's centre of mass moves exactly as the stepper moves one particle under gravity") {
  // With nothing pinned every spring and damping force cancels in the sum (Newton's third law), so the mean
  // position of a cloth started from any state obeys the stepper's recurrence for z'' = -g:
  //   explicit Euler:   z_n = z_0 + n h w_0 - g h^2 n (n - 1) / 2,
  //   symplectic Euler: z_n = z_0 + n h w_0 - g h^2 n (n + 1) / 2,
  // w_0 the mean initial velocity (and the same without g in x and y). The start is crumpled and its particles
  // move at random, so the springs and dampers are busy all along.
  const double g = 9.81, h = 0.01;
  const int n = 50;
  for (bool symplectic : {false, true}) {
    CAPTURE(symplectic);
    SceneParams p = params(7, 4, PinSet::none);
    p.stiffness = 100.0;
    p.damping = 1.0;
    const Scene scene(p);
    CHECK(scene.dof_count() == 3 * 7 * 4);
    ForceField field(scene);
    const auto stepper = make_stepper(symplectic ? "symplectic_euler" : "explicit_euler", field);

    std::mt19937 rng(21);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Vector x = scene.initial_positions(), v = scene.initial_velocities();
    for (Eigen::Index k = 0; k < x.size(); ++k) x[k] += 0.03 * unit(rng), v[k] += 2.0 * unit(rng);
    const auto mean = [&](const Vector& y) {
      Eigen::Vector3d m = Eigen::Vector3d::Zero();
      for (int s = 0; s < scene.free_count(); ++s) m += y.segment<3>(3 * s);
      return Eigen::Vector3d(m / scene.free_count());
    };
    const Eigen::Vector3d x0 = mean(x), w0 = mean(v);
    Vector f(scene.dof_count());
    field.forces(x, v, f);
    REQUIRE(f.cwiseAbs().maxCoeff() > 10.0);  // the springs do pull

    for (int k = 0; k < n; ++k) REQUIRE(stepper->step(h, x, v));
    const Eigen::Vector3d expected =
        x0 + n * h * w0 - Eigen::Vector3d(0, 0, g * h * h * n * (symplectic ? n + 1 : n - 1) / 2.0);
    const Eigen::Vector3d got = mean(x);
    CHECK(got.x() == doctest::Approx(expected.x()).epsilon(1e-11));
    CHECK(got.y() == doctest::Approx(expected.y()).epsilon(1e-11));
    CHECK(got.z() == doctest::Approx(expected.z()).epsilon(1e-11));
  }
}

TEST_CASE("--swing w starts a rigid turn about the edge j = N-1: v = v0 e_z - w e_x x (r - r_edge)") {
  // docs/model.md: the turn is about the line y = (N-1) d, z = 0, along x, and w > 0 lifts the far edge (y < y_edge),
  // so its angular velocity is -w e_x (right-hand rule). Written as the cross product, independently
  // of the library's z-only formula; a rigid motion stretches no spring at first order, so with the edge pinned
  // (its particles at rest on the axis) every spring's length rate (x_p - x_q) . (v_p - v_q) / l is zero.
  for (const double v0 : {0.0, -1.5}) {
    CAPTURE(v0);
    SceneParams p = params(5, 4, PinSet::edge);
    p.initial_velocity_z = v0;
    p.initial_swing = 3.0;
    const Scene scene(p);
    const Vector x = scene.initial_positions(), v = scene.initial_velocities();
    const Eigen::Vector3d axis(-1, 0, 0), on_axis(0, (p.grid.N - 1) * p.grid.d, 0);
    for (int s = 0; s < scene.free_count(); ++s) {
      const Eigen::Vector3d expected =
          Eigen::Vector3d(0, 0, v0) + p.initial_swing * axis.cross(Eigen::Vector3d(x.segment<3>(3 * s)) - on_axis);
      CHECK((v.segment<3>(3 * s) - expected).norm() <= 1e-14);
    }
    Vector all_x(3 * scene.particle_count()), all_v = Vector::Zero(3 * scene.particle_count());
    scene.all_positions(x, all_x);
    for (int s = 0; s < scene.free_count(); ++s) all_v.segment<3>(3 * scene.particle_of_slot(s)) = v.segment<3>(3 * s);
    if (v0 != 0) continue;  // a uniform v0 does stretch the springs to the pinned edge
    int springs = 0;
    for (const Spring& spring : scene.springs().springs) {
      const int a = scene.particle_of_slot(spring.p), b = scene.particle_of_slot(spring.q);
      const double rate = (all_x.segment<3>(3 * a) - all_x.segment<3>(3 * b)).dot(all_v.segment<3>(3 * a) -
                                                                                   all_v.segment<3>(3 * b));
      CHECK(std::abs(rate) <= 1e-14);
      ++springs;
    }
    CHECK(springs > 20);
  }
  // The far edge j = 0 moves at w (N-1) d, down for w < 0; the particles on the edge's line do not move.
  SceneParams p = params(3, 6, PinSet::none);
  p.initial_velocity_z = 0;
  p.initial_swing = -2.0;
  const Scene scene(p);
  const Vector v = scene.initial_velocities();
  CHECK(v[3 * scene.slot(p.grid.particle(1, 0)) + 2] == doctest::Approx(-2.0 * 5 * 0.1).epsilon(1e-14));
  CHECK(v[3 * scene.slot(p.grid.particle(1, 2)) + 2] == doctest::Approx(-2.0 * 3 * 0.1).epsilon(1e-14));
  CHECK(v[3 * scene.slot(p.grid.particle(1, 5)) + 2] == 0.0);
  p.initial_swing = std::nan("");
  CHECK_THROWS_AS(validate(p), InputError);
}

TEST_CASE("the report's cases are (50, 0), (200, 0), (200, 20), named as their folders, and change only K and D") {
  REQUIRE(report_cases.size() == 3);
  CHECK(report_cases[0].name() == "K50_D0");
  CHECK(report_cases[1].name() == "K200_D0");
  CHECK(report_cases[2].name() == "K200_D20");
  SceneParams base = params(6, 5, PinSet::edge);
  base.initial_velocity_z = -3;
  const SceneParams p = with_case(base, report_cases[2]);
  CHECK(p.stiffness == 200);
  CHECK(p.damping == 20);
  CHECK(p.grid.M == 6);
  CHECK(p.pins == PinSet::edge);
  CHECK(p.initial_velocity_z == -3);
}
