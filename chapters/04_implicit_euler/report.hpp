// Chapter 4's studies behind --report-runs, each in a file named for what it studies, and what they share: one run
// of the cloth with given Newton settings, the folders of the runs, the declared outputs, and the inputs every
// study reads (Study).
#pragma once

#include "integrators/simulate.hpp"
#include "model/report_cases.hpp"
#include "program/command_line.hpp"
#include "program/method_flags.hpp"
#include "program/output_spec.hpp"

#include <functional>
#include <string>

namespace ch04 {

/// How one run of the cloth ended.
struct Outcome {
  int status;
  cloth::RunResult result;
  std::string method;  ///< the stepper's name, as run.txt and the failure message give it
};

/// One run of the cloth with `newton` (validated before anything was written), outputs in `dir`.
Outcome run_cloth(const cloth::SceneParams& params, cloth::RunSettings run, const cloth::NewtonSettings& newton,
                  const std::string& dir, const std::string& program);

/// `newton` as full Newton on `solver` with the Jacobian `treatment`: the settings of the chapter's measured runs,
/// each of which fixes what it compares, whatever the command line chose.
cloth::NewtonSettings full_newton(cloth::NewtonSettings newton, cloth::LinearSolverKind solver,
                                  cloth::StiffnessTreatment treatment);

/// The report's three (K, D), each run with full Newton and with one iteration, in subfolders of `--out`.
std::string report_folder(const char* variant, const cloth::ReportCase& c);

/// The single runs behind the page's other measurements, each in a subfolder: the definite matrix's failure, the
/// stiff cloth at a large step, and conjugate gradients.
inline constexpr const char* measured_run_folders[] = {"definite_K50_D0", "stiff_K100000_h0.1", "cg_K50_D0"};

/// What `--report-runs` writes into `--out`, declared once (program/output_spec.hpp).
cloth::OutputList report_outputs();

/// What every study of `--report-runs` reads.
struct Study {
  const cloth::Options& opt;    ///< the scene and the run the command line describes
  cloth::NewtonSettings newton;  ///< the command line's Newton settings
  std::string dir;              ///< `--out`
  std::string program;          ///< the program's name, for the runs' summaries
  std::string command;          ///< the reader's command line, under every fragment
};

/// Full Newton against one Newton iteration at the report's three (K, D): report_runs.md, comparison.dat and a
/// folder per run. `newton_for(K, D)` gives the full-Newton settings at (K, D), as main checked them. Returns the
/// exit status of an interrupted run, else 0.
int full_against_one(const Study& study, const std::function<cloth::NewtonSettings(double, double)>& newton_for);

/// The residuals of Newton's iterations on one stiff step: residuals.dat and stiff_step.md.
void stiff_step(const Study& study);

/// What the Newton matrix's treatment costs in iterations, and the definite matrix's failed run:
/// iterations_*.dat, jacobian_treatments.md, definite_failure.txt. Returns the status of an interrupted run, else 0.
int newton_matrices(const Study& study);

/// The stiff cloth at a large step, and conjugate gradients on the report scene: stiff_large_step.md, cg_run.md.
/// Returns the status of an interrupted run, else 0.
int large_step_and_cg(const Study& study);

/// Implicit Euler's distance from RK4 at two steps: rk4_agreement.md, rk4_halving_ratio.md.
void agreement_with_rk4(const Study& study);

}  // namespace ch04
