// The residuals of Newton's iterations on one stiff step: quadratic convergence down to the rounding floor.
#include "report.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace ch04 {

using namespace cloth;

namespace {

// [stiff_step_residuals]
// The residual |r|_inf after each Newton iteration of the first step of the report scene at K = 1e5 N/m,
// h = 0.01 s (h omega_max ~ 10): exact Jacobian, sparse LU, tolerance tight enough to watch the sequence reach
// rounding.
std::vector<double> stiff_step_residuals(const SceneParams& report_scene) {
  const Scene scene(with_K_and_D(report_scene, 1e5, 0));
  ForceField field(scene);
  NewtonSettings newton;
  newton.solver = LinearSolverKind::lu;
  newton.treatment = StiffnessTreatment::exact;
  newton.tolerance = 1e-14;
  newton.max_iterations = 30;
  const auto made = make_newton_stepper("implicit_euler", field, {newton});
  NewtonStepper& stepper = *made;
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  stepper.step(0.01, x, v);  // if it fails the history still shows how far it got
  return stepper.residual_history();
}
// [stiff_step_residuals]

// residuals.dat for the figure (iteration k, |r_k|, |r_k| / |r_{k-1}|^2), and the page's table of the same.
void write_stiff_step(const std::vector<double>& r, const std::string& dir, const std::string& command) {
  OutputFile file(dir + "/residuals.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# first step of the report scene, K = 1e5, D = 0, h = 0.01, exact Jacobian, LU\n");
  std::fprintf(out, "# k |r_k|_inf |r_k|/|r_(k-1)|^2   (? : no ratio at k = 0, gnuplot's missing value)\n");
  std::printf("stiff step (K = 1e5, h = 0.01, exact Jacobian, LU): |r_k|_inf =");
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (k == 0) std::fprintf(out, "%zu %.6e ?\n", k, r[k]);
    else std::fprintf(out, "%zu %.6e %.6e\n", k, r[k], r[k] / (r[k - 1] * r[k - 1]));
    std::printf(" %.3g", r[k]);
  }
  std::printf("\n");
  file.commit();
  // The table stops at the rounding floor: the first iterate that no later one improves tenfold. The iterates
  // after it only wander around the floor, and are summed up in one row.
  MarkdownTable table({"Newton iteration k", "residual r_k (max norm) [N s]", "r_k / r_(k-1)^2"}, "rrr");
  std::size_t floor = 0;
  while (floor + 1 < r.size() && *std::min_element(r.begin() + static_cast<std::ptrdiff_t>(floor) + 1, r.end()) <
                                     0.1 * r[floor])
    ++floor;
  for (std::size_t k = 0; k <= floor && k < r.size(); ++k)
    table.add_row({std::to_string(k), format_number(r[k], 3),
                   k == 0 ? "" : k == floor ? "(rounding floor)" : format_number(r[k] / (r[k - 1] * r[k - 1]), 2)});
  if (floor + 1 < r.size()) {
    const auto [low, high] = std::minmax_element(r.begin() + static_cast<std::ptrdiff_t>(floor) + 1, r.end());
    table.add_row({std::to_string(floor + 1) + " to " + std::to_string(r.size() - 1),
                   format_number(*low, 2) + " to " + format_number(*high, 2), "(rounding floor)"});
  }
  write_table_fragment(dir + "/stiff_step.md", table, command);
}

}  // namespace

void stiff_step(const Study& study) {
  write_stiff_step(stiff_step_residuals(study.opt.scene), study.dir, study.command);
}

}  // namespace ch04
