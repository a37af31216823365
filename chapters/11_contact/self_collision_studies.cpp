// The self-collision studies of Chapter 11: the strip folding onto itself, and what the hash costs beside the
// forces as the strip grows.
#include "studies.hpp"

#include "base/format_number.hpp"
#include "contact/self_collision.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <chrono>
#include <cmath>

using namespace cloth;

namespace ch11 {

void fold_study(const Study& study) {
  const Grid grid{30, study.quick ? 100 : 200, 0.01};
  const double T = study.quick ? 1.0 : 1.5, h = 5e-4;
  const BuiltScene b = build_scene(SceneKind::fold, ContactFlags{}, &grid);
  ContactStepper stepper(make_stepper("symplectic_euler", *b.field), b.model);
  SelfCollision check(b.scene->initial_positions(), b.model.thickness);
  double closest = b.model.thickness;
  const SteppedRun run = step_run(stepper, b, h, T, 30, [&](const Vector& x) {
    closest = std::min(closest, check.closest_distance(x, 2));
  });
  const SelfCollisionWork& work = stepper.self_collision()->work();
  MarkdownTable table({"strip", "steps", "closest pair (rest > 2 thickness) after any step [% of thickness]",
                       "deepest in the ground [% of thickness]", "passes per step", "pairs parted per step",
                       "particles clamped"}, "lrrrrrr");
  const auto steps = static_cast<double>(run.steps);
  table.add_row({std::to_string(grid.M) + " x " + std::to_string(grid.N), std::to_string(run.steps),
                 format_fixed(100 * closest / b.model.thickness, 2),
                 format_number(100 * std::max(0.0, run.deepest) / b.model.thickness, 2),
                 format_fixed(static_cast<double>(work.passes) / steps, 2),
                 format_fixed(static_cast<double>(work.pairs_corrected) / steps, 1), std::to_string(work.clamped)});
  write_table_fragment(study.dir + "/fold.md", table, study.command);
  write_frames(study.dir + "/fold_frames.dat", grid, run.frames);
}

namespace {

// The strip folded like an accordion: layers of `rows` rows each, stacked 1.05 thickness apart, so that every
// particle has a layer above or below it within the hash's reach, as in a pile on the ground.
Vector accordion(const Grid& grid, int rows, double thickness) {
  Vector x(3 * grid.M * grid.N);
  for (int j = 0; j < grid.N; ++j) {
    const int layer = j / rows, along = layer % 2 == 0 ? j % rows : rows - 1 - j % rows;
    for (int i = 0; i < grid.M; ++i)
      x.segment<3>(3 * (j * grid.M + i)) = Eigen::Vector3d(i * grid.d, along * grid.d, (1 + 1.05 * layer) * thickness);
  }
  return x;
}

// The least of `repeats` wall times of f, in milliseconds: the least is the one the machine disturbed least.
template <class F>
double best_ms(int repeats, F f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace

// [hash_benchmark]
void hash_benchmark(const Study& study) {
  MarkdownTable table({"strip", "particles", "forces [ms]", "self-collision [ms]", "self-collision / forces",
                       "per particle [us]", "brute force [ms]"}, "lrrrrrr");
  const std::vector<int> lengths = {100, 200, 400, 800};
  for (const int n : lengths) {
    const Grid grid{30, n, 0.01};
    const BuiltScene b = build_scene(SceneKind::fold, ContactFlags{}, &grid);
    const Vector x0 = accordion(grid, 25, b.model.thickness);
    Vector x = x0, v = Vector::Zero(x0.size()), f(x0.size());
    SelfCollision self(b.scene->initial_positions(), b.model.thickness);
    const double forces = best_ms(20, [&] { b.field->forces(x0, v, f); });
    // A step's self-collision: the hash built and queried once, and one pass of the response.
    const double hash = best_ms(20, [&] {
      x = x0;
      self.find_candidates(x);
      self.resolve(x, v);
    });
    const double brute = best_ms(n <= 200 ? 3 : 1, [&] { (void)pairs_within_brute_force(x0, 1.5 * b.model.thickness); });
    const int particles = grid.M * grid.N;
    table.add_row({"30 x " + std::to_string(n), std::to_string(particles), format_fixed(forces, 3),
                   format_fixed(hash, 3), format_fixed(hash / forces, 2), format_fixed(1000 * hash / particles, 3),
                   format_fixed(brute, 1)});
  }
  write_table_fragment(study.dir + "/hash.md", table, study.command);
}
// [hash_benchmark]

}  // namespace ch11
