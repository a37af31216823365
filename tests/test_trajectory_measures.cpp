// Chapter 10's measures of a motion against a reference (analysis/trajectory_measures.hpp) on states made by hand
// with known answers, the rule that a level the rest state meets is no win, and the reference motion against the
// closed form of the single-spring oscillator.
#include <doctest/doctest.h>

#include "analysis/reference_trajectory.hpp"
#include "analysis/trajectory_measures.hpp"
#include "model/single_spring.hpp"

#include <cmath>
#include <stdexcept>

using namespace cloth;

namespace {

// Three particles in a row at rest, each frame a copy with the given particle moved by the given offset.
Frame frame(double t, int particle = 0, Eigen::Vector3d offset = Eigen::Vector3d::Zero()) {
  Frame f{t, Vector::Zero(9)};
  for (int p = 0; p < 3; ++p) f.positions[3 * p] = 0.1 * p;
  f.positions.segment<3>(3 * particle) += offset;
  return f;
}

}  // namespace

TEST_CASE("largest_distance is the largest particle distance, not a norm of the whole vector") {
  Vector a = Vector::Zero(6), b = Vector::Zero(6);
  b.segment<3>(0) = Eigen::Vector3d(0.3, 0.4, 0);   // 0.5 away
  b.segment<3>(3) = Eigen::Vector3d(0, 0.2, 0.1);   // sqrt(0.05) away
  CHECK(largest_distance(a, b) == doctest::Approx(0.5).epsilon(1e-15));
  CHECK_THROWS_AS((void)largest_distance(a, Vector::Zero(3)), std::invalid_argument);
}

TEST_CASE("trajectory_error: at T and the worst frame; a coarser run is compared at its own frames") {
  // The reference stands still; the run's particle 1 is 0.3 m off at t = 0.1 s and 0.2 m off (3-4-5) at T = 0.2 s.
  const std::vector<Frame> reference = {frame(0), frame(0.05), frame(0.1), frame(0.15), frame(0.2)};
  const std::vector<Frame> run = {frame(0), frame(0.1, 1, {0, 0, 0.3}), frame(0.2, 1, {0.12, 0.16, 0})};
  const TrajectoryError e = trajectory_error(run, reference);
  CHECK(e.at_end == doctest::Approx(0.2).epsilon(1e-14));
  CHECK(e.over_frames == doctest::Approx(0.3).epsilon(1e-14));
  CHECK(e.worst_time == 0.1);
  // A frame the reference does not have, and a run that stopped before T, are refused.
  CHECK_THROWS_AS((void)trajectory_error({frame(0), frame(0.07), frame(0.2)}, reference), std::invalid_argument);
  CHECK_THROWS_AS((void)trajectory_error({frame(0), frame(0.1)}, reference), std::invalid_argument);
}

TEST_CASE("motion_size is the rest state's distance from the reference, at T and over the frames") {
  // The reference's particle 2 swings out to 0.5 m and back to 0.25 m: the motion is 0.25 m at T, 0.5 m over all.
  const std::vector<Frame> reference = {frame(0), frame(0.5, 2, {0, 0, -0.5}), frame(1, 2, {0, -0.15, -0.2})};
  const TrajectoryError m = motion_size(reference);
  CHECK(m.at_end == doctest::Approx(0.25).epsilon(1e-14));
  CHECK(m.over_frames == doctest::Approx(0.5).epsilon(1e-14));
  CHECK(m.worst_time == 0.5);
}

TEST_CASE("the rule: a level the rest state meets is never a win; below the motion, the error decides") {
  // The four-corner sheet: motion 6.7 mm at T, so 1 cm is met by standing still, even by an exact run.
  CHECK(accuracy_verdict(0.0, 0.0067, 0.01) == AccuracyVerdict::met_by_rest);
  CHECK(accuracy_verdict(0.0067, 0.0067, 0.0067) == AccuracyVerdict::met_by_rest);
  // The curtain: motion 1.47 m, so 1 cm measures something.
  CHECK(accuracy_verdict(0.0035, 1.47, 0.01) == AccuracyVerdict::reached);
  CHECK(accuracy_verdict(0.79, 1.47, 0.01) == AccuracyVerdict::missed);
  CHECK(accuracy_verdict(0.01, 1.47, 0.01) == AccuracyVerdict::reached);
  CHECK(std::string(accuracy_verdict_name(AccuracyVerdict::met_by_rest)) == "met by standing still");
}

TEST_CASE("fastest_reaching never counts a level the rest state meets as a win") {
  // A sheet that moves 6.7 mm by T: its particle 2 sags 6.7 mm. Three runs of it: one exact but slow, one off by
  // 2 mm and fast, one that failed (NaN) and cost nothing.
  const std::vector<Frame> reference = {frame(0), frame(0.5, 2, {0, 0, -0.0067})};
  const double motion = motion_size(reference).at_end;
  REQUIRE(motion == doctest::Approx(0.0067).epsilon(1e-12));
  const std::vector<Frame> exact = reference;
  const std::vector<Frame> off = {frame(0), frame(0.5, 2, {0, 0, -0.0047})};
  const std::vector<RunCost> runs = {{trajectory_error(exact, reference).at_end, 2.0},
                                     {trajectory_error(off, reference).at_end, 0.5},
                                     {NAN, 0.0}};
  // 1 cm and the motion itself: met by standing still, so no run wins, not even the exact one.
  CHECK(fastest_reaching(runs, motion, 0.01) == -1);
  CHECK(fastest_reaching(runs, motion, motion) == -1);
  // 3 mm: the fast run (error 2 mm) wins; 1 mm: only the exact run reached it; 1e-20 m: nobody's; never the NaN.
  CHECK(fastest_reaching(runs, motion, 0.003) == 1);
  CHECK(fastest_reaching(runs, motion, 0.001) == 0);
  CHECK(fastest_reaching({{0.0, 1.0}, {NAN, 0.0}}, motion, 1e-20) == 0);
  CHECK(fastest_reaching({{1e-3, 1.0}}, motion, 1e-20) == -1);
  CHECK(met_by_standing_still(motion) == "met by standing still (the rest state is 0.0067 m from the reference)");
}

TEST_CASE("largest_strain of a hand-stretched 2 x 2 sheet") {
  SceneParams p;
  p.grid = Grid{2, 2, 0.1};
  p.pins = PinSet::none;
  const Scene scene(p);
  Vector all(12);
  scene.all_positions(scene.initial_positions(), all);
  CHECK(largest_strain(scene, all) == 0.0);
  // Particle (1, 1) moved out along the diagonal by 0.01 sqrt 2: the shear spring from (0, 0) grows from
  // 0.1 sqrt 2 to 0.11 sqrt 2 (strain 0.1), the structural ones to (0, 1) and (1, 0) from 0.1 to
  // sqrt(0.11^2 + 0.01^2) (strain 0.1045), the largest.
  all.segment<3>(3 * p.grid.particle(1, 1)) += Eigen::Vector3d(0.01, 0.01, 0);
  CHECK(largest_strain(scene, all) == doctest::Approx(std::hypot(0.11, 0.01) / 0.1 - 1).epsilon(1e-12));
  // Squashed to half its length, a spring's strain is 0.5 in magnitude.
  scene.all_positions(scene.initial_positions(), all);
  all[3 * p.grid.particle(1, 0)] = 0.05;
  all[3 * p.grid.particle(1, 1)] = 0.05;
  const double shear = std::hypot(0.05, 0.1) / (0.1 * std::sqrt(2.0)) - 1;  // -0.209
  CHECK(std::abs(shear) < 0.5);
  CHECK(largest_strain(scene, std::vector<Frame>{{0, all}}) == doctest::Approx(0.5).epsilon(1e-12));
}

TEST_CASE("free_edge_height averages the row j = 0; first_minimum_time finds the vertex of a sampled parabola") {
  const Grid grid{3, 4, 0.1};
  Frame f{0, Vector::Zero(3 * 12)};
  for (int i = 0; i < 3; ++i) {
    f.positions[3 * grid.particle(i, 0) + 2] = -0.1 * (i + 1);  // mean -0.2
    f.positions[3 * grid.particle(i, 3) + 2] = 5;                // the other edge: not counted
  }
  CHECK(free_edge_height(grid, {f})[0] == doctest::Approx(-0.2).epsilon(1e-14));
  // y = (t - 0.537)^2 - 1 sampled every 1/60 s: the three-point parabola is exact.
  std::vector<double> t, y, falling;
  for (int k = 0; k <= 60; ++k) {
    t.push_back(k / 60.0);
    y.push_back((t.back() - 0.537) * (t.back() - 0.537) - 1);
    falling.push_back(-t.back());
  }
  CHECK(first_minimum_time(t, y) == doctest::Approx(0.537).epsilon(1e-12));
  // A smooth non-quadratic curve: cos(2 pi t / 1.3) has its first minimum at 0.65, found to O(dt^2).
  std::vector<double> c;
  for (double s : t) c.push_back(std::cos(2 * M_PI * s / 1.3));
  CHECK(std::abs(first_minimum_time(t, c) - 0.65) < 1e-4);
  // A curve still falling at the horizon has no minimum inside it.
  CHECK(std::isnan(first_minimum_time(t, falling)));
  CHECK_THROWS_AS((void)first_minimum_time(t, {1.0}), std::invalid_argument);
}

TEST_CASE("energy_lost: what the run dissipated beyond the reference, as a fraction of a scale") {
  const Energy reference{2.0, -1.0, 0.5}, run{1.0, -1.2, 0.4};  // totals 1.5 and 0.2
  const EnergyLoss loss = energy_lost(run, reference, 4.0);
  CHECK(loss.joules == doctest::Approx(1.3).epsilon(1e-14));
  CHECK(loss.fraction == doctest::Approx(0.325).epsilon(1e-14));
}

TEST_CASE("the reference motion lands on every frame and matches the single-spring oscillator's closed form") {
  const double K = 400, D = 0.5, m = 1, s0 = -0.02, T = 1;
  SceneParams p = single_spring_params(K, D);
  p.mass = m;
  const Scene scene(p);
  ForceField field(scene);
  Vector x0, v0;
  single_spring_initial_state(scene, s0, x0, v0);
  const ReferenceTrajectory ref = reference_trajectory(field, x0, v0, T, 60, 1e-11);
  REQUIRE(ref.frames.size() == 61);
  double worst = 0;
  for (std::size_t k = 0; k < ref.frames.size(); ++k) {
    CHECK(ref.frames[k].t == doctest::Approx(k / 60.0).epsilon(1e-15));
    const double s = single_spring_exact(K, D, m, s0, ref.frames[k].t).s;
    // free particle (i, 0) rests at y = 0; displaced by s along y
    for (int i = 0; i < 2; ++i) worst = std::max(worst, std::abs(ref.frames[k].positions[3 * p.grid.particle(i, 0) + 1] - s));
  }
  CHECK(worst < 1e-9);
  CHECK(worst > 0);  // it is a numerical solution
  // The energy is recorded with the frames, and falls as the dampers work.
  CHECK(ref.energy.back().total() < ref.energy.front().total());
}
