// Chapter 10's fabric preset: the measured cotton of model/fabric.hpp at 20 to 153 particles per side on the same
// square metre, with each grid's spring constants, fastest lattice frequency and RK4's stable step.
#include "real_cloth.hpp"

#include "analysis/lattice_frequency.hpp"
#include "model/fabric.hpp"
#include "program/fragment.hpp"

#include <cmath>

using namespace cloth;

namespace ch10 {

void preset(const Settings& s) {
  const FabricMeasurements cotton;
  MarkdownTable t({"particles per side", "spacing d [m]", "particle mass m = ρ_A d² [kg]",
                   "k_s = k_sh [N/m]", "k_f [N/m]", "ω_max [rad/s]", "RK4's stable step [s]"},
                  "rrrrrrr");
  for (int n : {20, 39, 77, 153}) {
    const SceneParams p = fabric_scene(cotton, {0.95, n, 20.0});
    const double w = lattice_fastest_frequency({p.stiffness, p.stiffness, *p.flexion_stiffness, p.mass});
    t.add_row({format("%d", n), format("%.4g", p.grid.d), format("%.4g", p.mass), format("%.6g", p.stiffness),
               format("%.3g", *p.flexion_stiffness), format("%.4g", w), format("%.3g", 2 * std::sqrt(2.0) / w)});
  }
  write_table_fragment(s.out + "/preset.md", t, s.command);
}

}  // namespace ch10
