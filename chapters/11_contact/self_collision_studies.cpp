// The self-collision studies of Chapter 11: the strip folding onto itself, and what the hash costs beside the
// forces as the strip grows.
#include "studies.hpp"

#include "base/format_number.hpp"
#include "contact/self_collision.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/timing.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <string>

using namespace cloth;

namespace ch11 {

namespace {

// The strip folded like an accordion: layers of `rows` rows each, stacked 1.05 thickness apart, so that every
// particle has a layer above or below it within the hash's reach, as in a pile on the ground.
Vector accordion(const Grid& grid, int rows, double thickness) {
  Vector x(3 * grid.M * grid.N);
  for (int j = 0; j < grid.N; ++j) {
    const int layer = j / rows, along = layer % 2 == 0 ? j % rows : rows - 1 - j % rows;
    for (int i = 0; i < grid.M; ++i)
      x.segment<3>(3 * grid.particle(i, j)) = Eigen::Vector3d(i * grid.d, along * grid.d, (1 + 1.05 * layer) * thickness);
  }
  return x;
}

// The median, the fastest and the slowest of `repeats` runs of f after one untimed run, in milliseconds of the
// thread's processor time (program/timing.hpp). The chapter's ratios divide medians: a force evaluation takes some
// 50 microseconds, so short that a single run unlike the others moves the fastest of twenty by a third, and not
// the median.
struct Milliseconds {
  double median, fastest, slowest;
};
Milliseconds time_ms(int repeats, const std::function<void()>& f) {
  const Timing t = time_runs(f, {.runs = repeats, .warmup = 1, .repeat = 1});
  return {1e3 * t.median_cpu, 1e3 * t.fastest_cpu, 1e3 * t.slowest_cpu};
}

// "median (fastest-slowest)", the book's way of giving a time with its spread.
std::string with_spread(const Milliseconds& t, int digits) {
  std::string text = format_fixed(t.median, digits);
  text += " (";
  text += format_fixed(t.fastest, digits);
  text += '-';
  text += format_fixed(t.slowest, digits);
  text += ')';
  return text;
}

}  // namespace

void fold_study(const Study& study) {
  const auto [grid, T, h] = fold_study_run(study);
  const BuiltScene b = build_scene(SceneKind::fold, ContactFlags{}, &grid);
  ContactStepper stepper(make_stepper("symplectic_euler", *b.field), b.model);
  SelfCollision check(b.scene->initial_positions(), b.model.thickness);
  double closest = b.model.thickness;
  const SteppedRun run = step_run(stepper, b, h, T, 30, [&](const Vector& x) {
    closest = std::min(closest, check.closest_distance(x, 2));
  });
  const SelfCollisionWork& work = stepper.self_collision()->work();
  // One force evaluation per step (symplectic Euler), timed on the strip's last state.
  Vector f(run.x.size());
  const double forces = time_ms(20, [&] { b.field->forces(run.x, run.v, f); }).median;
  MarkdownTable table({"strip", "steps", "closest pair [%]", "deepest in the ground [%]", "passes per step",
                       "pairs parted per step", "particles clamped", "builds per step",
                       "distances per build and particle", "self-collision / forces", "hash / forces",
                       "passes / forces", "sweep / forces"}, "lrrrrrrrrrrrr");
  const auto steps = static_cast<double>(run.steps);
  table.add_row({std::to_string(grid.M) + " x " + std::to_string(grid.N), std::to_string(run.steps),
                 format_fixed(100 * closest / b.model.thickness, 2),
                 format_number(100 * std::max(0.0, run.deepest) / b.model.thickness, 2),
                 format_fixed(static_cast<double>(work.passes) / steps, 2),
                 format_fixed(static_cast<double>(work.pairs_corrected) / steps, 1), std::to_string(work.clamped),
                 format_fixed(static_cast<double>(work.builds) / steps, 2),
                 format_fixed(static_cast<double>(work.distance_tests) / static_cast<double>(work.builds) /
                                  static_cast<double>(grid.M * grid.N), 1),
                 format_fixed(1000 * work.seconds / steps / forces, 2),
                 format_fixed(1000 * (work.seconds - work.sweep_seconds - work.pass_seconds) / steps / forces, 2),
                 format_fixed(1000 * work.pass_seconds / steps / forces, 2),
                 format_fixed(1000 * work.sweep_seconds / steps / forces, 2)});
  write_table_fragment(study.dir + "/fold.md", table, study.command);
  write_scene_frames(study, "fold", b, run.frames);
}

// skin.md: the fold of fold.md run again with each skin s of the kept list (ContactModel::skin): how often a step
// rebuilds, how many candidates the list holds, and what self-collision costs beside one force evaluation.
void skin_study(const Study& study) {
  const auto [grid, T, h] = fold_study_run(study);
  MarkdownTable table({"skin s [thickness]", "reach 1 + 2 s [thickness]", "steps that built",
                       "candidates per particle and step", "passes per step", "self-collision / forces"}, "rrrrrr");
  for (const double skin : {0.125, 0.25, 0.375, 0.5}) {
    ContactFlags flags;
    flags.skin = skin;
    const BuiltScene b = build_scene(SceneKind::fold, flags, &grid);
    ContactStepper stepper(make_stepper("symplectic_euler", *b.field), b.model);
    const SteppedRun run = step_run(stepper, b, h, T, 1);
    const SelfCollisionWork& work = stepper.self_collision()->work();
    Vector f(run.x.size());
    const double forces = time_ms(20, [&] { b.field->forces(run.x, run.v, f); }).median;
    const auto steps = static_cast<double>(run.steps);
    table.add_row({format_number(skin, 3), format_number(1 + 2 * skin, 3),
                   format_fixed(static_cast<double>(work.builds) / steps, 2),
                   format_fixed(static_cast<double>(work.pairs_found) /
                                    static_cast<double>(work.builds + work.reuses) / (grid.M * grid.N), 2),
                   format_fixed(static_cast<double>(work.passes) / steps, 2),
                   format_fixed(1000 * work.seconds / steps / forces, 2)});
  }
  write_table_fragment(study.dir + "/skin.md", table, study.command);
}


// [hash_benchmark]
void hash_benchmark(const Study& study) {
  MarkdownTable table({"strip", "particles", "forces [ms]", "step with a build [ms]", "/ forces",
                       "step without [ms]", "/ forces", "distances tested per particle", "candidates per particle",
                       "brute force [ms]"}, "lrrrrrrrrr");
  // Each time at the first and the last strip, for the growth exponent p of time ~ particles^p.
  std::array<double, 4> first{}, last{};
  for (const int n : {100, 200, 400, 800}) {
    const Grid grid{30, n, 0.01};
    const BuiltScene b = build_scene(SceneKind::fold, ContactFlags{}, &grid);
    const Vector x0 = accordion(grid, 25, b.model.thickness);
    Vector x = x0, v = Vector::Zero(x0.size()), f(x0.size());
    SelfCollision self(b.scene->initial_positions(), b.model.thickness);
    const Milliseconds forces = time_ms(20, [&] { b.field->forces(x0, v, f); });
    // A step's self-collision with a build: the hash built and queried, and one pass of the response.
    const Milliseconds built = time_ms(20, [&] {
      x = x0;
      self.find_candidates(x);
      self.resolve(x, v);
    });
    // A step within the margin: the check of the kept list's margin, and one pass.
    const Milliseconds kept = time_ms(20, [&] {
      self.update_candidates(x);
      self.resolve(x, v);
    });
    const Milliseconds brute = time_ms(n <= 200 ? 3 : 1, [&] { (void)pairs_within_brute_force(x0, 1.5 * b.model.thickness); });
    const double particles = grid.M * grid.N;
    const SelfCollisionWork& w = self.work();
    table.add_row({"30 x " + std::to_string(n), format_fixed(particles, 0), with_spread(forces, 3),
                   with_spread(built, 3), format_fixed(built.median / forces.median, 2), with_spread(kept, 3),
                   format_fixed(kept.median / forces.median, 2),
                   format_fixed(static_cast<double>(w.distance_tests) / static_cast<double>(w.builds) / particles, 1),
                   format_fixed(static_cast<double>(self.candidates().size()) / particles, 2),
                   format_fixed(brute.median, 1)});
    (n == 100 ? first : last) = {forces.median, built.median, kept.median, brute.median};
  }
  const auto exponent = [&](std::size_t k) { return format_fixed(std::log(last[k] / first[k]) / std::log(8.0), 2); };
  table.add_row({"growth exponent, 3000 to 24 000", "", exponent(0), exponent(1), "", exponent(2), "", "", "",
                 exponent(3)});
  write_table_fragment(study.dir + "/hash.md", table, study.command);
}
// [hash_benchmark]

}  // namespace ch11
