// Chapter 11's measurement of a candidate list refreshed particle by particle, each particle with a skin of its
// own (contact/adaptive_skin.hpp), against the library's rebuilds of the spatial hash, on the fold.
#include "studies.hpp"

#include "base/format_number.hpp"
#include "contact/adaptive_skin.hpp"
#include "contact/self_collision.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"

#include <array>
#include <string>

using namespace cloth;

namespace ch11 {

namespace {

// The non-neighbour pairs of x closer than delta that `list` does not hold, by comparing every pair: the lists'
// independent check (it must stay 0).
long long missed_contacts(const AdaptiveSkinList& list, const Vector& x, const Vector& rest, double delta) {
  long long missed = 0;
  const auto n = static_cast<int>(x.size() / 3);
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if ((x.segment<3>(3 * b) - x.segment<3>(3 * a)).squaredNorm() < delta * delta &&
          (rest.segment<3>(3 * b) - rest.segment<3>(3 * a)).norm() > 2 * delta * (1 + 1e-9) && !list.holds(a, b))
        ++missed;
  return missed;
}

}  // namespace

// [adaptive_skin_study]
void adaptive_skin_study(const Study& study) {
  const auto [grid, T, h] = fold_study_run(study);
  const BuiltScene b = build_scene(SceneKind::fold, ContactFlags{}, &grid);
  const double delta = b.model.thickness;
  const Vector rest = b.scene->initial_positions();
  struct Variant {
    double max_radius;  // r_max [delta]
    bool follow;        // the frame follows the common motion, or stays on the ground
    long long missed = 0;
  };
  std::array<Variant, 4> variants{{{0.25, true}, {0.25, false}, {0.5, true}, {0.5, false}}};
  std::vector<AdaptiveSkinList> lists;
  for (const Variant& v : variants) lists.emplace_back(rest, delta, v.max_radius * delta, 0.25 * delta, v.follow);
  // One run of the library's stepper; each list follows its states, checked by brute force every 100 steps.
  ContactStepper stepper(make_stepper("symplectic_euler", *b.field), b.model);
  long long step = 0;
  const SteppedRun run = step_run(stepper, b, h, T, 1, [&](const Vector& x) {
    const bool check = ++step % 100 == 0;
    for (std::size_t k = 0; k < lists.size(); ++k) {
      lists[k].update(x);
      if (check) variants[k].missed += missed_contacts(lists[k], x, rest, delta);
    }
  });
  const auto steps = static_cast<double>(run.steps), particles = static_cast<double>(grid.M * grid.N);
  MarkdownTable table({"candidates", "particles queried per step", "mean radius [thickness]",
                       "distances per particle queried", "distances per step", "contacts missed"}, "lrrrrr");
  const SelfCollisionWork& work = stepper.self_collision()->work();
  table.add_row({"the hash rebuilt (skin 1/4, frame with the common motion)",
                 format_fixed(static_cast<double>(work.builds) * particles / steps, 0), "0.25",
                 format_fixed(static_cast<double>(work.distance_tests) / static_cast<double>(work.builds) / particles, 1),
                 format_fixed(static_cast<double>(work.distance_tests) / steps, 0), "0"});
  for (std::size_t k = 0; k < lists.size(); ++k) {
    const AdaptiveSkinList& list = lists[k];
    const auto queries = static_cast<double>(list.queries());
    table.add_row({"per particle, r_max = " + format_number(variants[k].max_radius, 2) + ", frame " +
                       (variants[k].follow ? "with the common motion" : "on the ground"),
                   format_fixed(queries / steps, 0), format_fixed(list.mean_radius() / delta, 2),
                   format_fixed(static_cast<double>(list.distance_tests()) / queries, 1),
                   format_fixed(static_cast<double>(list.distance_tests()) / steps, 0),
                   std::to_string(variants[k].missed)});
  }
  write_table_fragment(study.dir + "/adaptive_skin.md", table, study.command);
}
// [adaptive_skin_study]

}  // namespace ch11
