// The stiff cloth (K, D) = (5000, 20): how stiff it is for the study's steps, and what full and modified Newton
// cost on it for the L-stable methods and BDF2.
#include "studies.hpp"

#include "analysis/fastest_modes.hpp"
#include "analysis/stability_function.hpp"
#include "base/format_number.hpp"
#include "program/fragment.hpp"

#include <algorithm>
#include <cmath>

using namespace cloth;

namespace ch09 {
namespace {

// How stiff the stiff cloth is for the study's steps: its fastest mode at rest (where the damper's matrix is D/K
// times the stiffness matrix, so that mode has the damping rate c = (D/K) omega_max^2), the size of h lambda over
// the steps, and the largest step at which explicit RK4 is stable on that mode. Written to `path` as a sentence.
void write_stiffness(const SceneParams& params, const std::vector<double>& hs, const std::string& path) {
  const Scene scene(params);
  ForceField field(scene);
  const double omega = fastest_rest_frequency(field);
  const double c = fastest_damping_rate(field, scene.initial_positions(), Vector::Zero(scene.dof_count()));
  // The roots of lambda^2 + c lambda + omega^2 = 0: a conjugate pair when c < 2 omega, else two real ones.
  const Complex root = std::sqrt(Complex(c * c / 4 - omega * omega, 0));
  const Complex lambda = -c / 2 - root;
  const ButcherTableau& rk4 = *find_method("rk4").tableau;
  const double rk4_limit = stability_limit_along(
      [&](double h) { return std::abs(stability_function(rk4, h * lambda)) <= 1 + 1e-12; }, 1.0);
  const auto [h_min, h_max] = std::minmax_element(hs.begin(), hs.end());
  write_text_fragment(
      path, "At rest the fastest mode of (K, D) = (" + format_number(params.stiffness) + ", " +
                format_number(params.damping) + ") has ω_max = " + format_number(omega, 4) +
                " rad/s and the damping rate c = " + format_number(c, 4) + " 1/s" +
                (c < 2 * omega ? ", less than 2ω_max: an underdamped oscillation, λ = " : ": overdamped, λ = ") +
                format_number(lambda.real(), 4) +
                (c < 2 * omega ? " ± " + format_number(std::abs(lambda.imag()), 4) + "i" : "") +
                " 1/s, |λ| = " + format_number(std::abs(lambda), 4) + " 1/s. Over the study's steps h|λ| runs from " +
                format_number(*h_min * std::abs(lambda), 2) + " (h = " + format_number(*h_min) + " s) to " +
                format_number(*h_max * std::abs(lambda), 2) + " (h = " + format_number(*h_max) +
                " s), and explicit RK4 is stable on this mode for every h up to " + format_number(rk4_limit, 3) +
                " s.\n");
}

}  // namespace

void stiff_work_precision(const Study& study) {
  SceneParams stiff = report_cloth(study.opt.scene);
  stiff.stiffness = 5000;
  const std::vector<double> hs = study_steps(study.quick);
  write_stiffness(stiff, hs, study.dir + "/stiffness.md");
  // The figure shows the L-stable methods and BDF2; the others fail at the large steps (see the page).
  const WorkPrecision spec{stiff,
                           study_horizon,
                           hs,
                           reference_positions(stiff, study_horizon, 2e-5),
                           study.newton,
                           {NewtonVariant::full, NewtonVariant::modified},
                           study.quick ? 1 : 3,
                           {"implicit_euler", "sdirk2", "sdirk3", "bdf2"}};
  const std::vector<StudyRun> stiff_runs = work_precision(spec, study.dir + "/work_precision.dat");
  // Full against modified Newton at the smallest step, where every method converges.
  const std::string stiff_scene = std::string("(K, D) = (5000, 20), T = 0.4 s, h = ") + format_number(hs.back()) + " s";
  MarkdownTable work_table({stiff_scene, "Newton", "error [m]", "time [s]", "factorizations"}, "llrrr");
  for (const StudyRun& r : stiff_runs)
    if (r.h == hs.back())
      work_table.add_row({r.title, newton_variant_name(r.variant), format_number(r.error, 2),
                          format_number(r.seconds, 2), std::to_string(r.factorizations)});
  write_table_fragment(study.dir + "/work_precision.md", work_table, study.command);
}

}  // namespace ch09
