// Chapter 10's map: the peers' plain force loop against the book's forces and definite Newton matrix (an
// independent implementation of the same model), and the map's rules read from hand-made parts: the fastest run
// that reached a level, the prediction from a ladder's last two rungs, and a level the rest state meets.
#include "../chapters/06_speed_vs_error/plain_fabric.hpp"
#include "map_part_file.hpp"
#include "program_runner.hpp"

#include "model/force_field.hpp"
#include "model/scene.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace cloth;

TEST_CASE("the plain fabric's accelerations and definite Jacobian are the book's, on the swinging curtain with "
          "compressed springs") {
  SceneParams p;
  p.grid = {6, 6, 0.05};
  p.stiffness = 1e4;
  p.damping = 0.01;
  p.mass = 6.25e-4;
  p.pins = PinSet::edge;
  p.initial_velocity_z = 0;
  p.initial_swing = -4;
  const Scene scene(p);
  ForceField field(scene);
  ch06::PlainFabric plain(6, 6, 0.05, p.stiffness, p.damping, p.mass, p.gravity, 0, true, p.initial_swing);
  const int P = scene.particle_count(), n = scene.dof_count();
  // A moving state 1 cm off rest, enough to compress some springs (the definite rule's clamp then acts).
  std::vector<double> y = plain.initial_state();
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  int compressed_checked = 0;
  for (int particle = 0; particle < P; ++particle) {
    const int s = scene.slot(particle);
    if (s >= scene.free_count()) continue;
    for (int k = 0; k < 3; ++k) {
      CHECK(y[3 * (P + particle) + k] == doctest::Approx(v[3 * s + k]).epsilon(1e-15));  // same start, swing included
      const double dx = 1e-2 * std::sin(1.3 * (3 * particle + k)), dv = 0.1 * std::cos(0.7 * (3 * particle + k));
      y[3 * particle + k] += dx, x[3 * s + k] += dx;
      y[3 * (P + particle) + k] += dv, v[3 * s + k] += dv;
    }
  }
  std::vector<double> dydt(y.size());
  plain.rhs(y.data(), dydt.data());
  Vector a(n);
  field.acceleration(x, v, a);
  // The book's A(1) = M - df/dv - df/dx (definite) against m (I - J_v - J_x) from the plain loop's dy'/dy, applied
  // to one vector z over the free coordinates.
  SparseMatrix A = field.pattern();
  field.newton_matrix(x, v, 1.0, StiffnessTreatment::definite, A);
  std::vector<double> J(static_cast<std::size_t>(plain.nonzeros()));
  plain.jacobian(y.data(), J.data(), true);
  Vector z(n), Az(n), plain_Az = Vector::Zero(n);
  for (int k = 0; k < n; ++k) z[k] = std::sin(0.37 * k + 0.2);
  Az = A * z;
  const auto& starts = plain.column_starts();
  const auto& rows = plain.rows();
  for (int half = 0; half < 2; ++half)
    for (int particle = 0; particle < P; ++particle)
      for (int b = 0; b < 3; ++b) {
        const int s = scene.slot(particle);
        if (s >= scene.free_count()) continue;
        const int c = half * 3 * P + 3 * particle + b;
        for (long k = starts[static_cast<std::size_t>(c)]; k < starts[static_cast<std::size_t>(c) + 1]; ++k) {
          const long r = rows[static_cast<std::size_t>(k)] - 3 * P;
          if (r < 0) continue;  // the upper half
          const int rs = scene.slot(static_cast<int>(r / 3));
          if (rs < scene.free_count()) plain_Az[3 * rs + r % 3] -= p.mass * J[static_cast<std::size_t>(k)] * z[3 * s + b];
        }
      }
  plain_Az += p.mass * z;
  double worst_a = 0, worst_A = 0;
  for (int particle = 0; particle < P; ++particle) {
    const int s = scene.slot(particle);
    if (s < scene.free_count())
      for (int k = 0; k < 3; ++k) worst_a = std::max(worst_a, std::abs(dydt[3 * (P + particle) + k] - a[3 * s + k]));
  }
  worst_A = (Az - plain_Az).cwiseAbs().maxCoeff();
  CHECK(worst_a <= 1e-12 * a.cwiseAbs().maxCoeff());
  CHECK(worst_A <= 1e-12 * Az.cwiseAbs().maxCoeff());
  // The clamp acted: some spring of the state is compressed.
  for (int i = 0; i + 1 < 6; ++i) {
    const int q = i * 6, r = (i + 1) * 6;
    double l2 = 0;
    for (int k = 0; k < 3; ++k) l2 += std::pow(y[3 * q + k] - y[3 * r + k], 2);
    compressed_checked += std::sqrt(l2) < 0.05 ? 1 : 0;
  }
  CHECK(compressed_checked > 0);
}

#ifdef CLOTH_HAVE_CH10_MAP

TEST_CASE("the map's tables: the fastest run that reached a level, a prediction from the last two rungs, and a "
          "level the rest state meets") {
  cloth_test::ScratchDir dir;
  // The curtain: motion 1.5 m, so plausible is 7.5 cm, which symplectic Euler reaches (2 cm in 0.2 s) and 1 cm
  // not. rk4 reaches 1 mm in 0.5 s; the peer 1 cm in 0.2 s and then 3 mm in 0.8 s: its 1 mm time from
  // error ~ seconds^-q, q = log(10/3) / log(4), is 0.8 (3)^(1/q) s.
  cloth_test::write_map_part(dir.path() / "map_curtain_20_1e5.dat", "curtain_20_1e5", 0.6, 1.5,
             "book rk4 book \"h = 1/2760\" 1656 5e-01 1e-4 5e-04 ok\n"
             "book symplectic_euler book \"h = 1/3900\" 2340 2e-01 1e-3 2e-02 ok\n"
             "peer cvode_bdf plain \"tol = 0.1\" 100 2e-01 1e-3 1e-02 ok\n"
             "peer cvode_bdf plain \"tol = 0.01\" 400 8e-01 1e-3 3e-03 ok\n");
  // The swing scene with a motion of 8 mm: 1 cm is met by standing still.
  cloth_test::write_map_part(dir.path() / "map_swing_20_1e5.dat", "swing_20_1e5", 0.6, 0.008,
             "book rk4 book \"h = 1/2760\" 1656 5e-01 1e-4 5e-05 ok\n");
  // A ladder whose last rung failed (its errors written as nan) predicts nothing, though its first two rungs
  // converge: the failed row is read, and only a ladder's last two rungs may extrapolate.
  cloth_test::write_map_part(dir.path() / "map_curtain_40_1e5.dat", "curtain_40_1e5", 0.6, 1.5,
             "book implicit_euler/one/cg book \"h = 1/30\" 18 1e-01 5e-2 5e-02 ok\n"
             "book implicit_euler/one/cg book \"h = 1/60\" 36 2e-01 2e-2 2e-02 ok\n"
             "book implicit_euler/one/cg book \"h = 1/120\" 3 4e-01 nan nan failed\n");
  const cloth_test::ProgramRun run = cloth_test::run_chapter("ch10_map", {"--tables", "--out", "."}, dir.path());
  REQUIRE(run.status == 0);
  const std::string curtain = cloth_test::read_text(dir.path() / "map_curtain.md");
  const std::string swing = cloth_test::read_text(dir.path() / "map_swing.md");
  CHECK(curtain.find("| 1 mm | rk4, h = 1/2760: 0.5 s |") != std::string::npos);
  const double q = std::log(10.0 / 3) / std::log(4.0), predicted = 0.8 * std::pow(3.0, 1 / q);
  char expected[64];
  std::snprintf(expected, sizeof expected, "*predicted* cvode_bdf (plain forces): %.2g s", predicted);
  CHECK(curtain.find(expected) != std::string::npos);
  CHECK(curtain.find("| 1 cm | rk4, h = 1/2760: 0.5 s | cvode_bdf, tol = 0.1 (plain forces): 0.2 s |") !=
        std::string::npos);
  CHECK(curtain.find("| plausible: 7.5 cm | symplectic_euler, h = 1/3900: 0.2 s |") != std::string::npos);
  CHECK(curtain.find("| 40 x 40 | 10⁵ | 1.5 m to 0.6 s | 1 mm | none | none | none |") != std::string::npos);
  CHECK(swing.find("| 1 cm | met by standing still |") != std::string::npos);
  CHECK(swing.find("| 1 mm | rk4, h = 1/2760: 0.5 s |") != std::string::npos);
}

TEST_CASE("ch10_map refuses a part it does not know, with one line naming what is accepted") {
  cloth_test::ScratchDir dir;
  for (const char* part : {"curtain_20_2e5", "corners_20_1e5", "curtain_2_1e5", "curtain_20_1e5x", "curtain_20_1e5,"}) {
    const cloth_test::ProgramRun run = cloth_test::run_chapter("ch10_map", {"--part", part, "--out", "."}, dir.path());
    CHECK(run.status == 2);
    CHECK(run.err.find("--part") != std::string::npos);
    CHECK(cloth_test::entry_count(dir.path()) == 0);
  }
  const cloth_test::ProgramRun none = cloth_test::run_chapter("ch10_map", {"--out", "."}, dir.path());
  CHECK(none.status == 2);
  CHECK(none.err.find("expected --part, --all, --quick or --tables") != std::string::npos);
}
#endif
