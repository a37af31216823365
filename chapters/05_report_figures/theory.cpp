// The linear theory of Chapters 2-4 for every (K, D) of the chapter: the fastest mode's h omega and explicit
// Euler's energy factor, the fastest damped mode at rest and on the deformed cloth, and explicit Euler's measured
// energy growth against that prediction (see experiments.hpp). Symbols as on the model page: mu_max is the largest
// eigenvalue of L = sum u u^T, omega_max = sqrt(K mu_max / m), c_max = D mu_max / m.
#include "experiments.hpp"

#include "analysis/fastest_modes.hpp"
#include "base/format_number.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ch05 {

using namespace cloth;

namespace {

// [stiffness_eigenvalue]
// mu_max, the largest eigenvalue of L = sum u u^T (one 3x3 block per spring), at the rest state. At rest no spring
// is under tension, so -df/dx = K L and the highest mode's frequency is omega_max = sqrt(K mu_max / m). The
// projected dampers have -df/dv = D L, the same matrix with D for K, so the fastest damped mode decays at the rate
// c_max = D mu_max / m. These set the stability limits of Chapters 2-4 for each (K, D).
double rest_stiffness_mu_max(const SceneParams& base) {
  const Scene scene(with_K_and_D(base, 1, 0));  // K = 1: -df/dx is L itself
  ForceField field(scene);
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  const Vector x = scene.initial_positions();
  field.jacobians(x, Vector::Zero(x.size()), dfdx, dfdv);
  // analysis/fastest_modes.hpp: power iteration on -M^{-1} df/dx; with unit masses that is L
  return largest_rate(dfdx, 1.0);
}

// The same mu_max on a deformed cloth (every particle's positions in grid order), from the dampers' -df/dv = D L:
// u now points wherever the springs point, so mu_max moves away from its rest value, and c_max = D mu_max / m
// with it.
double deformed_mu_max(const SceneParams& base, const Vector& positions) {
  const Scene scene(with_K_and_D(base, 1, 1));  // any K > 0: df/dv of the projected dampers does not depend on it
  ForceField field(scene);
  Vector x(scene.dof_count());
  for (int s = 0; s < scene.free_count(); ++s) x.segment<3>(3 * s) = positions.segment<3>(3 * scene.particle_of_slot(s));
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, Vector::Zero(x.size()), dfdx, dfdv);
  return largest_rate(dfdv, 1.0);  // D = 1 and unit masses: L
}
// [stiffness_eigenvalue]

}  // namespace

void write_theory(const std::vector<Run>& runs, const Options& opt, const Settings& settings) {
  const SceneParams& sp = opt.scene;
  const double h = opt.run.dt, T = opt.run.t_end, m = sp.mass;
  const double mu = rest_stiffness_mu_max(sp);
  OutputFile theory(opt.run.out_dir + "/theory.txt");
  std::fprintf(theory.get(),
               "mu_max = %.6g  # largest eigenvalue of L = sum u u^T at rest: omega_max = sqrt(K mu_max / m), "
               "c_max = D mu_max / m\n",
               mu);
  std::printf("\nrest state: mu_max = %.4g (largest eigenvalue of L = sum u u^T; omega_max = sqrt(K mu_max / m), "
              "c_max = D mu_max / m)\n", mu);
  std::printf("%5s %4s %10s %9s %15s %15s %9s\n", "K", "D", "omega_max", "h omega", "EE factor/step", "factor^(T/h)",
              "h c_max");
  // The page's tables: the undamped modes per K, the damped ones per D (theory.md).
  // HTML subscripts: a fragment's formulas are not typeset (program/fragment.hpp).
  MarkdownTable per_K({"K [N/m]", "ω<sub>max</sub> [1/s]", "h ω<sub>max</sub>",
                       "explicit Euler's energy factor a step, 1 + (h ω<sub>max</sub>)²",
                       "the same over T = " + format_number(T) + " s"}, "rrrrr");
  MarkdownTable per_D({"D [N s/m]", "c<sub>max</sub> [1/s]", "h c<sub>max</sub>"}, "rrr");
  for (const double K : sweep_K) {
    const double omega = std::sqrt(K * mu / m), ho = h * omega;
    per_K.add_row({format_number(K), format_number(omega, 4), format_fixed(ho, 3), format_fixed(1 + ho * ho, 3),
                   format_number(std::pow(1 + ho * ho, T / h), 3)});
    for (const double D : sweep_D) {
      const double c = D * mu / m;
      std::fprintf(theory.get(),
                   "K = %g D = %g omega_max = %.4g h_omega = %.4g explicit_euler_energy_factor_per_step = %.4g "
                   "over_T = %.4g h_c_max = %.4g\n",
                   K, D, omega, ho, 1 + ho * ho, std::pow(1 + ho * ho, T / h), h * c);
      if (D == 0 || K == 200)
        std::printf("%5g %4g %10.4g %9.4g %15.4g %15.4g %9.4g\n", K, D, omega, ho, 1 + ho * ho,
                    std::pow(1 + ho * ho, T / h), h * c);
    }
  }
  for (const double D : sweep_D)
    if (D > 0) per_D.add_row({format_number(D), format_number(D * mu / m, 4), format_fixed(h * D * mu / m, 3)});
  write_text_fragment(opt.run.out_dir + "/theory.md",
                      "At rest, μ<sub>max</sub> = " + format_number(mu, 4) + ", and at h = " + format_number(h) +
                          " s:\n\n" +
                          per_K.markdown() + "\n" + per_D.markdown() + "\n" + measured_by_line(settings.command));

  // The damped runs' fastest damped mode on the cloth as it deforms: h c_max against the real-axis stability
  // limits, 2 for explicit Euler and 2.785 for RK4 (Chapter 3).
  MarkdownTable deformed(
      {"implicit Euler's run", "t [s]", "μ<sub>max</sub> of the deformed cloth", "h c<sub>max</sub>"}, "lrrr");
  for (std::size_t r = 0; r < methods.size() * report_cases.size(); ++r) {
    const Run& run = runs[r];
    if (run.D == 0 || run.method != "implicit_euler") continue;
    const std::size_t stride = std::max<std::size_t>(1, run.result.frames.size() / 4);
    for (std::size_t k = 0; k < run.result.frames.size(); k += stride) {
      const Frame& f = run.result.frames[k];
      const double mu_d = deformed_mu_max(sp, f.positions), hc = h * run.D * mu_d / m;
      std::fprintf(theory.get(), "deformed K = %g D = %g t = %g mu_max = %.4g h_c_max = %.4g\n", run.K, run.D, f.t,
                   mu_d, hc);
      std::printf("implicit Euler K = %g, D = %g, t = %4.2f s: mu_max = %.4g, h c_max = %.4g\n", run.K, run.D, f.t,
                  mu_d, hc);
      deformed.add_row({k == 0 ? "K = " + format_number(run.K) + ", D = " + format_number(run.D) : "",
                        format_number(f.t, 3), format_number(mu_d, 4), format_fixed(hc, 2)});
    }
  }
  theory.commit();
  write_table_fragment(opt.run.out_dir + "/deformed_damping.md", deformed, settings.command);
}

void write_growth(const std::vector<Run>& runs, const Options& opt, const Settings& settings,
                  const EnergyReference& reference) {
  const double h = opt.run.dt, mu = rest_stiffness_mu_max(opt.scene);
  const std::string ratio = reference.launch ? "E/E(0)" : "E/E_ref";
  MarkdownTable table({"explicit Euler", "predicted factor a step, 1 + (h ω<sub>max</sub>)²", "from t [s]",
                       "to t [s]",
                       ratio + " at the start", ratio + " at the end", "measured factor a step"},
                      "lrrrrrr");
  for (std::size_t r = 0; r < methods.size() * report_cases.size(); ++r) {
    const Run& run = runs[r];
    if (run.method != "explicit_euler" || run.D != 0) continue;
    const double ho = h * std::sqrt(run.K * mu / opt.scene.mass);
    // The last quarter of the sane part of the run: late enough that the fastest modes dominate the energy.
    const std::vector<EnergySample>& e = run.result.energy;
    const double t_end = e.back().t;
    std::size_t first = 0;
    while (first + 1 < e.size() && e[first].t < 0.75 * t_end) ++first;
    const double steps = static_cast<double>(e.size() - 1 - first);
    const double start = e[first].energy.total(), end = e.back().energy.total();
    table.add_row({"K = " + format_number(run.K) + ", D = 0", format_fixed(1 + ho * ho, 3),
                   format_number(e[first].t, 3), format_number(t_end, 3), format_number(start / reference.joules, 3),
                   format_number(end / reference.joules, 3),
                   steps > 0 && start > 0 && end > 0 ? format_fixed(std::pow(end / start, 1 / steps), 3) : "n/a"});
  }
  write_table_fragment(opt.run.out_dir + "/growth.md", table, settings.command);
}

}  // namespace ch05
