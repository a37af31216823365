// The report's three configurations of the cloth, (K, D) = (50, 0), (200, 0), (200, 20), and "the report scene
// with this K and D": defined once, for every chapter that compares methods on them and for the tests.
#pragma once

#include "base/format_number.hpp"
#include "model/scene.hpp"

#include <array>
#include <string>

namespace cloth {

/// One configuration: spring stiffness K [N/m] and damping D [N s/m].
struct ReportCase {
  double K, D;
  /// "K50_D0": how folders and files are named after the case.
  [[nodiscard]] std::string name() const {
    std::string n = "K";  // appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) on "K" + std::string
    n += format_number(K);
    n += "_D";
    n += format_number(D);
    return n;
  }
};

/// The report's configurations, in the order of its figures: soft and undamped, stiff and undamped, stiff and
/// damped.
inline constexpr std::array<ReportCase, 3> report_cases = {{{50, 0}, {200, 0}, {200, 20}}};

/// `base` with its stiffness set to K and its damping to D; everything else (grid, pins, launch) unchanged.
inline SceneParams with_K_and_D(SceneParams base, double K, double D) {
  base.stiffness = K;
  base.damping = D;
  return base;
}
inline SceneParams with_case(const SceneParams& base, const ReportCase& c) { return with_K_and_D(base, c.K, c.D); }

}  // namespace cloth
