// The three spring families of the report (structural, shear, flexion), built once per scene from the rest
// configuration and stored contiguously, grouped by family, so that force loops stream through them.
#pragma once

#include "model/grid.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cloth {

/// The spring families of a mass-spring cloth (Provot 1995; the report's Figure 1).
enum class SpringFamily : int {
  structural = 0,  ///< (i,j)-(i+1,j) and (i,j)-(i,j+1): resists stretch, rest length d
  shear = 1,       ///< (i,j)-(i+1,j+1) and (i+1,j)-(i,j+1): resists shear, rest length d sqrt 2
  flexion = 2      ///< (i,j)-(i+2,j) and (i,j)-(i,j+2): resists bending, rest length 2 d
};
inline constexpr int spring_family_count = 3;
inline constexpr std::array<SpringFamily, 3> all_spring_families = {SpringFamily::structural, SpringFamily::shear,
                                                                    SpringFamily::flexion};

/// Lower-case name used on the command line and in output: "structural", "shear", "flexion".
const char* family_name(SpringFamily family);

/// A set of spring families, e.g. the scene's `--springs structural,shear`.
struct FamilySet {
  std::array<bool, 3> on = {true, true, true};
  [[nodiscard]] bool contains(SpringFamily f) const { return on[static_cast<int>(f)]; }
  static FamilySet all() { return {}; }
  static FamilySet only(SpringFamily f) {
    FamilySet s{{false, false, false}};
    s.on[static_cast<int>(f)] = true;
    return s;
  }
};

/// One spring between two particles. p and q index the scene's particle slots (free particles first).
struct Spring {
  std::int32_t p;
  std::int32_t q;
  double rest_length;  ///< L0 [m], the distance of p and q in the rest configuration
};

/// Half-open range [begin, end) of springs of one family inside SpringSet::springs.
struct SpringRange {
  int begin = 0;
  int end = 0;
  [[nodiscard]] int size() const { return end - begin; }
};

/// All springs of a scene, one family after another.
struct SpringSet {
  std::vector<Spring> springs;
  std::array<SpringRange, 3> family;  ///< where each family's springs lie in `springs`

  [[nodiscard]] int count(SpringFamily f) const { return family[static_cast<int>(f)].size(); }
  [[nodiscard]] int size() const { return static_cast<int>(springs.size()); }
};

/// Closed-form number of springs of a family on an M x N grid, for checks and the book:
/// structural (M-1)N + M(N-1), shear 2(M-1)(N-1), flexion (M-2)N + M(N-2) (each term only when positive).
int spring_count(SpringFamily family, int M, int N);

/// Builds the springs of the chosen families; `slot_of_particle[grid.particle(i,j)]` names each endpoint's slot.
/// Rest lengths are measured from the rest configuration, not typed in.
SpringSet build_springs(const Grid& grid, FamilySet families, const std::vector<int>& slot_of_particle);

}  // namespace cloth
