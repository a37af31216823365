// Chapter 11's count of the work a refitted hierarchy of mesh patches would do on the fold, beside the hash's: the
// distances a step must test when the boxes are refitted every step and no candidate list is kept.
#include "studies.hpp"

#include "base/format_number.hpp"
#include "contact/self_collision.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace cloth;

namespace ch11 {

namespace {

// A leaf of the hierarchy: the particles of a k x k block of the grid, their bounding box grown by half the
// thickness on every side (two boxes overlap when their particles may be closer than the thickness), and the unit
// normals at its particles.
struct Leaf {
  int bi, bj;  // the block's place in the grid of blocks
  Eigen::Vector3d low, high;
  std::vector<Eigen::Vector3d> normals;
};

// The unit normal of the grid's surface at particle (i, j), from the differences of its neighbours along i and j
// (one-sided at the edges).
Eigen::Vector3d normal_at(const Grid& g, const Vector& x, int i, int j) {
  const auto p = [&](int a, int b) -> Eigen::Vector3d {
    return x.segment<3>(3 * g.particle(std::clamp(a, 0, g.M - 1), std::clamp(b, 0, g.N - 1)));
  };
  return (p(i + 1, j) - p(i - 1, j)).cross(p(i, j + 1) - p(i, j - 1)).normalized();
}

std::vector<Leaf> leaves_of(const Grid& g, const Vector& x, int k, double delta) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<Leaf> leaves;
  for (int a = 0; a < g.M; a += k)
    for (int b = 0; b < g.N; b += k) {
      Leaf leaf{a / k, b / k, Eigen::Vector3d::Constant(inf), Eigen::Vector3d::Constant(-inf), {}};
      for (int i = a; i < std::min(a + k, g.M); ++i)
        for (int j = b; j < std::min(b + k, g.N); ++j) {
          const Eigen::Vector3d y = x.segment<3>(3 * g.particle(i, j));
          leaf.low = leaf.low.cwiseMin(y);
          leaf.high = leaf.high.cwiseMax(y);
          leaf.normals.push_back(normal_at(g, x, i, j));
        }
      leaf.low.array() -= delta / 2;
      leaf.high.array() += delta / 2;
      leaves.push_back(std::move(leaf));
    }
  return leaves;
}

// [patch_hierarchy_count]
// Whether every normal of the two leaves (a leaf with itself, or two neighbouring leaves: a connected patch) has a
// positive component along their mean: the normal half of Volino and Magnenat-Thalmann's test that a patch cannot
// pass through itself, with the mean as its direction. Their other half, on the patch's outline, can only keep a
// pair the normals skip, and a patch that cannot pass through itself may still bring two particles closer than the
// thickness (a steep, narrow ridge), so the count below is a generous one for the hierarchy.
bool flat_together(const Leaf& a, const Leaf& b) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Leaf* leaf : {&a, &b})
    for (const Eigen::Vector3d& n : leaf->normals) mean += n;
  mean.normalize();
  for (const Leaf* leaf : {&a, &b})
    for (const Eigen::Vector3d& n : leaf->normals)
      if (!(n.dot(mean) > 0)) return false;
  return true;
}

struct LeafCount {
  double overlapping = 0;  // leaf pairs whose boxes overlap
  double distances = 0;    // particle pairs of those leaves
  double culled = 0;       // the same, less the pairs of neighbouring leaves flat together
};

// One state's work with leaves of k x k particles: the pairs within each leaf (unless it is flat by itself), and
// every pair of distinct leaves whose boxes overlap, its particles compared pair by pair.
void count(const Grid& g, const Vector& x, int k, double delta, LeafCount& c) {
  const std::vector<Leaf> leaves = leaves_of(g, x, k, delta);
  for (std::size_t p = 0; p < leaves.size(); ++p) {
    const auto n = static_cast<double>(leaves[p].normals.size());
    c.distances += n * (n - 1) / 2;
    if (!flat_together(leaves[p], leaves[p])) c.culled += n * (n - 1) / 2;
    for (std::size_t q = p + 1; q < leaves.size(); ++q) {
      const Leaf &a = leaves[p], &b = leaves[q];
      if ((a.low.array() > b.high.array()).any() || (b.low.array() > a.high.array()).any()) continue;
      const auto pairs = static_cast<double>(a.normals.size() * b.normals.size());
      c.overlapping += 1;
      c.distances += pairs;
      const bool neighbours = std::abs(a.bi - b.bi) <= 1 && std::abs(a.bj - b.bj) <= 1;
      if (!(neighbours && flat_together(a, b))) c.culled += pairs;
    }
  }
}
// [patch_hierarchy_count]

}  // namespace

void patch_hierarchy_study(const Study& study) {
  const auto [grid, T, h] = fold_study_run(study);
  const BuiltScene b = build_scene(SceneKind::fold, ContactFlags{}, &grid);
  const double delta = b.model.thickness;
  constexpr std::array<int, 4> sizes{1, 2, 3, 4};  // 1 x 1: the fewest distances, the most boxes
  std::array<LeafCount, sizes.size()> counts{};
  // The library's run; every 10th state is counted as a step of the hierarchy would meet it.
  ContactStepper stepper(make_stepper("symplectic_euler", *b.field), b.model);
  long long step = 0, sampled = 0;
  const SteppedRun run = step_run(stepper, b, h, T, 1, [&](const Vector& x) {
    if (++step % 10 != 0) return;
    ++sampled;
    for (std::size_t s = 0; s < sizes.size(); ++s) count(grid, x, sizes[s], delta, counts[s]);
  });
  const auto particles = static_cast<double>(grid.M * grid.N), samples = static_cast<double>(sampled);
  MarkdownTable table({"detection", "overlapping leaf pairs per leaf and step", "distances per particle and step",
                       "with flat neighbouring leaves skipped"}, "lrrr");
  const SelfCollisionWork& work = stepper.self_collision()->work();
  table.add_row({"the hash, rebuilt when a particle leaves the skin (1/4 thickness)", "",
                 format_fixed(static_cast<double>(work.distance_tests) / static_cast<double>(run.steps) / particles, 1),
                 ""});
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    const int k = sizes[s];
    const auto leaves = static_cast<double>(((grid.M + k - 1) / k) * ((grid.N + k - 1) / k));
    table.add_row({"hierarchy refitted every step, leaves of " + std::to_string(k) + " x " + std::to_string(k),
                   format_fixed(counts[s].overlapping / samples / leaves, 2),
                   format_fixed(counts[s].distances / samples / particles, 1),
                   format_fixed(counts[s].culled / samples / particles, 1)});
  }
  write_table_fragment(study.dir + "/patch_hierarchy.md", table, study.command);
}

}  // namespace ch11
