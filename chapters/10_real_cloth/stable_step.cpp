// Chapter 10's explicit stable step on the fabric: predicted from the lattice's fastest frequency (Chapter 7's
// stability intervals), beside the finite cloth's own fastest frequency, and measured by bisection.
#include "real_cloth.hpp"

#include "analysis/fastest_modes.hpp"
#include "analysis/lattice_frequency.hpp"
#include "program/fragment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace cloth;

namespace ch10 {

namespace {

// [stable_step]
// Bisection (in log h) between half and twice the predicted step: `halvings` bisections leave the answer within
// a factor 4^(1/2^halvings), 2 % after 6.
double measured_stable_step(const Scene& scene, const std::string& method, double predicted, int halvings, int steps) {
  double stable = 0.5 * predicted, unstable = 2 * predicted;
  if (!stays_bounded(scene, method, stable, steps) || stays_bounded(scene, method, unstable, steps)) return NAN;
  for (int k = 0; k < halvings; ++k) {
    const double mid = std::sqrt(stable * unstable);
    (stays_bounded(scene, method, mid, steps) ? stable : unstable) = mid;
  }
  return stable;
}
// [stable_step]

}  // namespace

double stability_reach(const std::string& method) { return method == "rk4" ? 2 * std::sqrt(2.0) : 2.0; }

void stable_steps(const Settings& s, const std::vector<double>& stiffnesses) {
  MarkdownTable table({"grid", "K [N/m]", "ω_max, lattice [rad/s]", "ω_max, this cloth [rad/s]",
                       "symplectic Euler: predicted / measured h [s]", "RK4: predicted / measured h [s]"},
                      "lrrrrr");
  double worst[2] = {0, 0};  // the largest relative difference of prediction and measurement, per method
  std::string dat = "# n K omega_lattice omega_cloth se_predicted se_measured rk4_predicted rk4_measured\n";
  for (int n : s.quick ? std::vector<int>{20} : std::vector<int>{20, 39}) {
    for (double K : stiffnesses) {
      if (s.quick && K != 1e5) continue;
      const SceneParams p = fabric(n, K);
      const Scene scene(p);
      ForceField field(scene);
      const double lattice = lattice_fastest_frequency({K, K, K, p.mass});
      const double cloth_omega = fastest_rest_frequency(field);
      const double se = 2 / lattice, rk = 2 * std::sqrt(2.0) / lattice;
      const int halvings = s.quick ? 6 : 9, steps = s.quick ? 1000 : 2000;
      const double se_m = measured_stable_step(scene, "symplectic_euler", se, halvings, steps);
      const double rk_m = measured_stable_step(scene, "rk4", rk, halvings, steps);
      table.add_row({format("%d x %d", n, n), stiffness_text(K), format("%.4g", lattice), format("%.4g", cloth_omega),
                     format("%.3g / %.3g", se, se_m), format("%.3g / %.3g", rk, rk_m)});
      worst[0] = std::max(worst[0], std::abs(se_m / se - 1));
      worst[1] = std::max(worst[1], std::abs(rk_m / rk - 1));
      dat += format("%d %g %.6g %.6g %.6g %.6g %.6g %.6g\n", n, K, lattice, cloth_omega, se, se_m, rk, rk_m);
      std::printf("stable step %dx%d K %g: omega lattice %.4g cloth %.4g; SE %.3g/%.3g RK4 %.3g/%.3g\n", n, n, K,
                  lattice, cloth_omega, se, se_m, rk, rk_m);
    }
  }
  write_table_fragment(s.out + "/stable_step.md", table, s.command);
  write_text_fragment(s.out + "/stable_step_agreement.md",
                      format("The prediction holds to %.1f %% for symplectic Euler and to %.1f %% for RK4.",
                             100 * worst[0], 100 * worst[1]));
  write_text(s.out, "stable_step.dat", dat);
}

}  // namespace ch10
