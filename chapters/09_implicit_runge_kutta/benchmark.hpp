// What the files of ch09_sundials_benchmark share: one SUNDIALS run of the cloth (CVODE or ARKODE, KLU on the
// analytic Jacobian), one timed run of either side for the comparisons, and the comparisons themselves.
#pragma once

#include "rk4_reference.hpp"

#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/command_line.hpp"
#include "program/sundials.hpp"

#include <cmath>
#include <string>

namespace ch09 {

/// How a SUNDIALS run ended and what it did.
struct Outcome {
  bool ok = false;
  cloth::SundialsEnd end;  ///< the status in the model page's terms, and SUNDIALS' own flag
  double seconds = 0;      ///< the thread's processor time of the integration alone
  long steps = 0, newton_iterations = 0, setups = 0, convergence_failures = 0;
  long long rhs_evaluations = 0, jacobian_evaluations = 0;  ///< the right-hand side's and the Jacobian's
  double t = 0, failed_t = 0;  ///< the time reached; the time the step that failed was heading for
};

/// What a SUNDIALS run integrates with: `solver` ("cvode-bdf", "arkode-esdirk32", "arkode-esdirk43",
/// "arkode-dirk", "arkode-backward-euler"), the horizon, the tolerances, the fixed step of backward Euler, CVODE's
/// largest order, and the Jacobian's df/dx (exact, or as the book's Newton matrix of that treatment holds it).
struct SundialsSettings {
  std::string solver;
  double T = 0, rtol = 1e-6, atol = 1e-6, h = 0;
  int max_order = 5;
  cloth::StiffnessTreatment treatment = cloth::StiffnessTreatment::exact;
};

/// One SUNDIALS run of the scene from its initial state: the outcome, and the final free positions and velocities
/// in x and v.
Outcome sundials_run(const SundialsSettings& settings, cloth::ForceField& field, cloth::Vector& x, cloth::Vector& v);

/// One run of the comparison: who ran, with what, the error it reached and the processor seconds it took.
struct Timed {
  std::string solver, setting;
  double error = NAN, seconds = INFINITY;
  /// The work: factorizations (SUNDIALS: linear solver setups), Jacobian evaluations, Newton iterations and
  /// evaluations of the forces.
  long long factorizations = 0, jacobians = 0, newton_iterations = 0, forces = 0;
};

/// What a timed run of the book's is compared on: the horizon, the reference positions at it, the repeats.
struct Timing {
  double T;
  const cloth::Vector& reference;
  int repeats;
};

/// A registered implicit method at the fixed step h, Newton (`variant`) stopped at newton_tol: best of the repeats;
/// its final positions in `x_out` when given.
Timed fixed_step_run(cloth::ForceField& field, const std::string& method, double h, double newton_tol,
                     cloth::NewtonVariant variant, const Timing& timing, cloth::Vector* x_out = nullptr);

/// A controlled run of an embedded pair at the error tolerance `tol`, with the chapter's defaults for one.
Timed controlled_run(cloth::ForceField& field, const std::string& method, double tol, const Timing& timing);

/// One SUNDIALS run of `settings` (its T the timing's) at rtol = atol = tol, KLU on the analytic Jacobian: best of
/// the repeats, named by `who`.
Timed sundials_timed_run(cloth::ForceField& field, SundialsSettings settings, double tol, const std::string& who,
                         const Timing& timing);

/// The comparison on the stiff cloth (5000, 20): stiff_runs.dat, stiff_comparison.md, stiff_work.md and
/// stiff_reference.md in `dir`.
void stiff_comparison(const cloth::SceneParams& base, bool quick, const std::string& dir, const std::string& command);

/// Implicit Euler on the report scene, ARKODE's against the book's: report_scene.md in `dir`.
void report_scene_comparison(const cloth::SceneParams& base, bool quick, const std::string& dir,
                             const std::string& command);

/// One SUNDIALS run of the command line's scene: final.dat and run.txt in the run's folder, the summary on stdout
/// (with `compare`, the error against RK4). Returns the exit status.
int single_run(const cloth::Options& opt, const SundialsSettings& settings, bool compare, const std::string& program);

}  // namespace ch09
