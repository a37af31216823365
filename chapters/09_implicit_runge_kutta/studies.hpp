// What the files of ch09_implicit_runge_kutta share: the method the command line chose (a registry row or a tableau
// file, with Newton's settings and step control), one run of it, and the chapter's studies behind --report-runs,
// each in a file named for what it studies.
#pragma once

#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/command_line.hpp"
#include "program/output_spec.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ch09 {

/// Newton's tolerance as a fraction of the step control's error tolerance (Hairer & Wanner 1996, IV.8, kappa).
inline constexpr double newton_kappa = 0.1;

/// What the command line chose: a registered implicit method or a tableau file, Newton's settings, step control.
struct MethodChoice {
  std::string argument = "sdirk2";  ///< `--tableau` as given
  const cloth::Method* row = nullptr;  ///< the registry's row, or nullptr for a tableau file
  cloth::ImplicitTableau tableau;      ///< the tableau, for a Runge-Kutta method (empty for a multistep one)
  cloth::NewtonSettings newton;
  std::optional<double> tol;  ///< `--tol`: step control

  [[nodiscard]] bool multistep() const { return row != nullptr && row->family == cloth::MethodFamily::multistep; }
};

/// A registered method by its name, or else a tableau file; the message lists the registered names.
MethodChoice choose(const std::string& argument);

/// The stepper of `choice` on `field`.
std::unique_ptr<cloth::NewtonStepper> make_method(const MethodChoice& choice, cloth::ForceField& field);

/// The methods the studies compare: every registered method StageNewton solves, in the registry's order.
std::vector<MethodChoice> study_methods(const cloth::NewtonSettings& newton);

/// One run of the chosen method on `params`, outputs in run.out_dir; returns report()'s exit status, and the run's
/// result in `kept` when given.
int run_cloth(const cloth::SceneParams& params, const cloth::RunSettings& run, const MethodChoice& choice,
              const std::string& program, cloth::RunResult* kept = nullptr);

/// What `--report-runs` writes into `--out`, declared once (program/output_spec.hpp).
cloth::OutputList report_outputs();

/// What every study of `--report-runs` reads.
struct Study {
  const cloth::Options& opt;    ///< the scene and the run the command line describes
  cloth::NewtonSettings newton;  ///< the command line's Newton settings
  bool quick;                   ///< `--quick`: fewer steps and one timing per run
  std::string dir;              ///< `--out`
  std::string program;          ///< the program's name, for the runs' summaries
  std::string command;          ///< the reader's command line, under every fragment
};

/// Every method on the undamped cloth: energy_summary.dat, energy_summary.md and a folder per method. Returns 0, or
/// 128 + signal when a run was interrupted.
int energy_study(const Study& study);

/// The observed orders on (K, D) = (200, 20) over T = 0.4 s: orders.dat and orders.md.
void orders_study(const Study& study);

/// The Newton variants' work against precision on the stiff cloth (5000, 20): stiffness.md, work_precision.dat and
/// work_precision.md.
void stiff_work_precision(const Study& study);

/// The report's damped cloth (200, 20) and the study's steps and horizon, shared by the orders and the stiff study.
cloth::SceneParams report_cloth(const cloth::SceneParams& base);
std::vector<double> study_steps(bool quick);
inline constexpr double study_horizon = 0.4;

/// The free particles' final positions of RK4 at h_ref: the reference of the accuracy studies.
cloth::Vector reference_positions(const cloth::SceneParams& p, double T, double h_ref);

/// One run of the accuracy studies, for the page's tables.
struct StudyRun {
  std::string title;
  cloth::NewtonVariant variant;
  double h, error, seconds;
  long long factorizations;
};

/// What work_precision runs: each method of `only` (every one when empty) with each Newton variant at each step,
/// timed as the best of `repeats`.
struct WorkPrecision {
  cloth::SceneParams scene;
  double T;
  std::vector<double> steps;
  cloth::Vector reference;
  cloth::NewtonSettings newton;
  std::vector<cloth::NewtonVariant> variants;
  int repeats = 1;
  std::vector<std::string> only;
};

/// The runs of `spec`, one line per run in `path` (one gnuplot index per method and variant); returns them.
std::vector<StudyRun> work_precision(const WorkPrecision& spec, const std::string& path);

}  // namespace ch09
