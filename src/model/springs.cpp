// Spring topology of the grid: which particle pairs each family joins, and their rest lengths.
#include "model/springs.hpp"

#include <algorithm>

namespace cloth {

const char* family_name(SpringFamily family) {
  switch (family) {
    case SpringFamily::structural: return "structural";
    case SpringFamily::shear: return "shear";
    case SpringFamily::flexion: return "flexion";
  }
  return "?";
}

int spring_count(SpringFamily family, int M, int N) {
  const auto pos = [](int n) { return std::max(n, 0); };
  switch (family) {
    case SpringFamily::structural: return pos(M - 1) * N + M * pos(N - 1);
    case SpringFamily::shear: return 2 * pos(M - 1) * pos(N - 1);
    case SpringFamily::flexion: return pos(M - 2) * N + M * pos(N - 2);
  }
  return 0;
}

namespace {

// The neighbour offsets (di, dj) each family joins (i, j) to; every unordered pair appears once.
struct Offset {
  int di;
  int dj;
};
constexpr Offset structural_offsets[] = {{1, 0}, {0, 1}};
constexpr Offset flexion_offsets[] = {{2, 0}, {0, 2}};

}  // namespace

SpringSet build_springs(const Grid& grid, FamilySet families, const std::vector<int>& slot_of_particle) {
  SpringSet set;
  int total = 0;
  for (SpringFamily f : all_spring_families) {
    if (families.contains(f)) total += spring_count(f, grid.M, grid.N);
  }
  set.springs.reserve(static_cast<std::size_t>(total));

  const auto add = [&](int i0, int j0, int i1, int j1) {
    const double rest = (grid.rest_position(i0, j0) - grid.rest_position(i1, j1)).norm();
    set.springs.push_back({slot_of_particle[grid.particle(i0, j0)], slot_of_particle[grid.particle(i1, j1)], rest});
  };
  const auto add_offsets = [&](auto const& offsets) {
    for (int i = 0; i < grid.M; ++i)
      for (int j = 0; j < grid.N; ++j)
        for (const Offset& o : offsets)
          if (i + o.di < grid.M && j + o.dj < grid.N) add(i, j, i + o.di, j + o.dj);
  };

  for (SpringFamily f : all_spring_families) {
    auto& range = set.family[static_cast<int>(f)];
    range.begin = set.size();
    if (families.contains(f)) {
      switch (f) {
        case SpringFamily::structural: add_offsets(structural_offsets); break;
        case SpringFamily::flexion: add_offsets(flexion_offsets); break;
        case SpringFamily::shear:
          // Both diagonals of every grid cell.
          for (int i = 0; i + 1 < grid.M; ++i)
            for (int j = 0; j + 1 < grid.N; ++j) {
              add(i, j, i + 1, j + 1);
              add(i + 1, j, i, j + 1);
            }
          break;
      }
    }
    range.end = set.size();
  }
  return set;
}

}  // namespace cloth
