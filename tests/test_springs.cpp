// The spring topology against independent truth: the pairs each family joins are found again by brute force
// over all particle pairs of the rest grid (distance d, d sqrt 2, 2d), counted, and compared with the closed
// forms of cloth::spring_count; grids too small to be a cloth are refused.
#include <doctest/doctest.h>

#include "program/command_line.hpp"
#include "base/input_error.hpp"
#include "model/scene.hpp"

#include <array>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace cloth;

namespace {

using Pair = std::pair<int, int>;  // an unordered particle pair, smaller particle number first

Pair ordered(int a, int b) { return a < b ? Pair{a, b} : Pair{b, a}; }

// Every particle pair of the rest grid at distance L0 (to rounding), found without any knowledge of the
// neighbour offsets: on an integer lattice the only offsets of length 1, sqrt 2 and 2 are (1,0), (1,1) and
// (2,0) up to sign and swap, so distance alone identifies each family.
std::set<Pair> pairs_at_distance(const Grid& g, double L0) {
  std::set<Pair> pairs;
  const int n = g.particle_count();
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      const double dist = (g.rest_position(a / g.N, a % g.N) - g.rest_position(b / g.N, b % g.N)).norm();
      if (std::abs(dist - L0) <= 1e-9 * L0) pairs.insert({a, b});
    }
  return pairs;
}

double family_rest_length(SpringFamily f, double d) {
  switch (f) {
    case SpringFamily::structural: return d;
    case SpringFamily::shear: return d * std::sqrt(2.0);
    case SpringFamily::flexion: return 2 * d;
  }
  return 0;
}

// The particle pairs of one family as the scene built them; also checks no pair is stored twice.
std::set<Pair> scene_pairs(const Scene& scene, SpringFamily f) {
  std::set<Pair> pairs;
  const SpringRange r = scene.springs().family[static_cast<int>(f)];
  for (int k = r.begin; k < r.end; ++k) {
    const Spring& s = scene.springs().springs[static_cast<std::size_t>(k)];
    const bool inserted = pairs.insert(ordered(scene.particle_of_slot(s.p), scene.particle_of_slot(s.q))).second;
    CHECK_MESSAGE(inserted, "spring ", k, " of family ", family_name(f), " is stored twice");
  }
  return pairs;
}

SceneParams grid_params(int M, int N, double d = 0.1) {
  SceneParams p;
  p.grid = Grid{M, N, d};
  p.pins = PinSet::none;  // a 2 x 2 grid pinned at its corners has nothing left to simulate
  return p;
}

}  // namespace

TEST_CASE("each family joins exactly the pairs at distance d, d sqrt 2, 2d, and the closed-form counts hold") {
  struct Case {
    int M, N;
    double d;
  };
  const Case cases[] = {{2, 2, 0.1}, {2, 7, 0.1}, {7, 2, 0.3}, {3, 3, 0.1}, {5, 8, 0.25}, {20, 20, 0.1}};
  for (const Case& c : cases) {
    CAPTURE(c.M);
    CAPTURE(c.N);
    const Scene scene(grid_params(c.M, c.N, c.d));
    int total = 0;
    for (SpringFamily f : all_spring_families) {
      CAPTURE(family_name(f));
      const std::set<Pair> truth = pairs_at_distance(scene.grid(), family_rest_length(f, c.d));
      CHECK(scene_pairs(scene, f) == truth);
      CHECK(scene.springs().count(f) == static_cast<int>(truth.size()));
      CHECK(spring_count(f, c.M, c.N) == static_cast<int>(truth.size()));
      total += static_cast<int>(truth.size());
    }
    CHECK(scene.springs().size() == total);
  }
}

TEST_CASE("the report's 20 x 20 cloth has 760 structural, 722 shear and 720 flexion springs") {
  const Scene scene(grid_params(20, 20));
  CHECK(scene.springs().count(SpringFamily::structural) == 760);
  CHECK(scene.springs().count(SpringFamily::shear) == 722);
  CHECK(scene.springs().count(SpringFamily::flexion) == 720);
  CHECK(scene.springs().size() == 2202);
}

TEST_CASE("rest lengths are measured from the rest grid: d, d sqrt 2 and 2d") {
  for (double d : {0.1, 0.37}) {
    CAPTURE(d);
    const Scene scene(grid_params(5, 6, d));
    for (SpringFamily f : all_spring_families) {
      const SpringRange r = scene.springs().family[static_cast<int>(f)];
      REQUIRE(r.size() > 0);
      for (int k = r.begin; k < r.end; ++k)
        CHECK(scene.springs().springs[static_cast<std::size_t>(k)].rest_length ==
              doctest::Approx(family_rest_length(f, d)).epsilon(1e-14));
    }
  }
}

TEST_CASE("only the chosen spring families are built") {
  SceneParams p = grid_params(4, 5);
  p.families = FamilySet{{true, false, true}};
  const Scene scene(p);
  CHECK(scene.springs().count(SpringFamily::structural) == 31);  // 3*5 + 4*4
  CHECK(scene.springs().count(SpringFamily::shear) == 0);
  CHECK(scene.springs().count(SpringFamily::flexion) == 22);     // 2*5 + 4*3
  CHECK(scene.springs().size() == 53);
}

TEST_CASE("a 2 x N grid has flexion springs along its long side only") {
  for (const auto& [M, N] : {std::pair{2, 6}, std::pair{6, 2}}) {
    CAPTURE(M);
    CAPTURE(N);
    const Scene scene(grid_params(M, N));
    const Grid& g = scene.grid();
    const SpringRange r = scene.springs().family[static_cast<int>(SpringFamily::flexion)];
    // Along the long side: (i, j)-(i, j+2) for a 2 x N grid, 2 (N - 2) of them; none across the short side,
    // which would need a particle i = 2.
    CHECK(r.size() == 2 * (std::max(M, N) - 2));
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = scene.springs().springs[static_cast<std::size_t>(k)];
      const int a = scene.particle_of_slot(s.p), b = scene.particle_of_slot(s.q);
      const int di = std::abs(a / g.N - b / g.N), dj = std::abs(a % g.N - b % g.N);
      if (M == 2) CHECK((di == 0 && dj == 2));
      else CHECK((di == 2 && dj == 0));
    }
  }
}

TEST_CASE("grids smaller than 2 x 2 are refused by the scene and by --grid") {
  for (const auto& [M, N] : {std::pair{1, 1}, std::pair{0, 5}, std::pair{5, 1}, std::pair{-3, 4}}) {
    CAPTURE(M);
    CAPTURE(N);
    CHECK_THROWS_AS(Scene(grid_params(M, N)), InputError);
  }
  const CommandLine cli("test_springs", "grid validation");
  for (const char* text : {"1x1", "0x5", "5x1", "x5", "3x", "3by3", "2.5x4"}) {
    CAPTURE(text);
    const char* argv[] = {"test_springs", "--grid", text};
    std::string message;
    try {
      (void)cli.parse(3, argv);
    } catch (const InputError& e) {
      message = e.what();
    }
    CHECK(message.rfind("--grid: ", 0) == 0);  // the one-line message names the flag first
  }
  // The smallest cloth is accepted.
  const char* ok[] = {"test_springs", "--grid", "2x2", "--pins", "none"};
  CHECK(cli.parse(5, ok).scene.grid.particle_count() == 4);
}
