// The linear theory of Chapters 2-4 for every (K, D) of the chapter: the fastest mode's h omega and explicit
// Euler's energy factor, and the fastest damped mode at rest and on the deformed cloth (see experiments.hpp).
#include "experiments.hpp"

#include "analysis/fastest_modes.hpp"
#include "program/output.hpp"

#include <cmath>
#include <cstdio>

namespace ch05 {

using namespace cloth;

namespace {

// [stiffness_eigenvalue]
// Largest eigenvalue lambda of -df/dx / (m K) at the rest state. At rest no spring is under tension, so
// -df/dx = K sum u u^T (one 3x3 block per spring) and the highest mode's frequency is omega_max = sqrt(lambda K / m).
// The projected dampers have -df/dv = D sum u u^T, the same matrix with D for K, so the fastest damped mode decays
// at rate lambda D / m. These set the stability limits of Chapters 2-4 for each (K, D).
double rest_stiffness_eigenvalue(const SceneParams& base) {
  const Scene scene(with_K_and_D(base, 1, 0));
  ForceField field(scene);
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  const Vector x = scene.initial_positions();
  field.jacobians(x, Vector::Zero(x.size()), dfdx, dfdv);
  return largest_rate(dfdx, base.mass);  // analysis/fastest_modes.hpp: power iteration on -M^{-1} df/dx
}

// The same damping eigenvalue, lambda_D = largest eigenvalue of sum u u^T / m, on a deformed cloth (every particle's
// positions in grid order): u now points wherever the springs point, so lambda_D moves away from its rest value.
double damping_eigenvalue(const SceneParams& base, const Vector& positions) {
  const Scene scene(with_K_and_D(base, 1, 1));  // any K > 0: df/dv of the projected dampers does not depend on it
  ForceField field(scene);
  Vector x(scene.dof_count());
  for (int s = 0; s < scene.free_count(); ++s) x.segment<3>(3 * s) = positions.segment<3>(3 * scene.particle_of_slot(s));
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, Vector::Zero(x.size()), dfdx, dfdv);
  return largest_rate(dfdv, base.mass);
}
// [stiffness_eigenvalue]

}  // namespace

void write_theory(const std::vector<Run>& runs, const Options& opt) {
  const SceneParams& sp = opt.scene;
  const double h = opt.run.dt, T = opt.run.t_end;
  const double lambda = rest_stiffness_eigenvalue(sp);
  OutputFile theory(opt.run.out_dir + "/theory.txt");
  std::fprintf(theory.get(), "lambda_max = %.6g  # of -df/dx / (m K) at rest: omega_max = sqrt(lambda K / m)\n", lambda);
  std::printf("\nrest-state stiffness eigenvalue lambda_max = %.4g (omega_max = sqrt(lambda K / m))\n", lambda);
  std::printf("%5s %4s %10s %9s %15s %15s %12s\n", "K", "D", "omega_max", "h omega", "EE factor/step", "factor^(T/h)",
              "h lambda D/m");
  for (const double K : sweep_K)
    for (const double D : sweep_D) {
      const double omega = std::sqrt(lambda * K / sp.mass), ho = h * omega;
      const double rate = h * lambda * D / sp.mass;
      std::fprintf(theory.get(),
                   "K = %g D = %g omega_max = %.4g h_omega = %.4g explicit_euler_energy_factor_per_step = %.4g "
                   "over_T = %.4g h_lambda_D_over_m = %.4g\n",
                   K, D, omega, ho, 1 + ho * ho, std::pow(1 + ho * ho, T / h), rate);
      if (D == 0 || K == 200)
        std::printf("%5g %4g %10.4g %9.4g %15.4g %15.4g %12.4g\n", K, D, omega, ho, 1 + ho * ho,
                    std::pow(1 + ho * ho, T / h), rate);
    }
  // The damped runs' fastest damped mode on the cloth as it deforms: h lambda_D D / m against the real-axis
  // stability limits, 2 for explicit Euler and 2.785 for RK4 (Chapter 3).
  for (std::size_t r = 0; r < methods.size() * report_cases.size(); ++r) {
    const Run& run = runs[r];
    if (run.D == 0 || run.method != "implicit_euler") continue;
    for (std::size_t k = 0; k < run.result.frames.size(); k += run.result.frames.size() / 4) {
      const Frame& f = run.result.frames[k];
      const double lambda_d = damping_eigenvalue(sp, f.positions);
      std::fprintf(theory.get(), "deformed_damping K = %g D = %g t = %g lambda_D = %.4g h_lambda_D_D_over_m = %.4g\n",
                   run.K, run.D, f.t, lambda_d, h * lambda_d * run.D / sp.mass);
      std::printf("implicit Euler K = %g, D = %g, t = %4.2f s: lambda_D = %.4g, h lambda_D D / m = %.4g\n", run.K,
                  run.D, f.t, lambda_d, h * lambda_d * run.D / sp.mass);
    }
  }
  theory.commit();
}

}  // namespace ch05
