// Chapter 5's experiments: the report's runs (every method at every report case) and the K x D sweep, run in
// parallel; what a run's energy and sag say; and the data files each figure and table is drawn from.
#pragma once

#include "integrators/simulate.hpp"
#include "model/report_cases.hpp"
#include "program/command_line.hpp"

#include <string>
#include <vector>

namespace ch05 {

// [report_grid]
/// The chapter's methods (registry names), in the order of the figures' rows.
inline const std::vector<std::string> methods = {"explicit_euler", "symplectic_euler", "rk4", "implicit_euler"};

/// The report's six figures (Figures 2 to 7): which method at which report case, with its own caption.
struct ReportFigure {
  int number;
  std::string method;
  int report_case;  ///< index into cloth::report_cases
  std::string caption_method;
};
inline const std::vector<ReportFigure> report_figures = {
    {2, "explicit_euler", 1, "Euler's method"},          {3, "explicit_euler", 0, "Explicit Euler's method"},
    {4, "explicit_euler", 2, "Explicit Euler's method"}, {5, "rk4", 1, "Runge-Kutta's method"},
    {6, "rk4", 2, "Runge-Kutta's method"},               {7, "implicit_euler", 0, "Implicit Euler's method"}};

/// The sweep: every K against every D, per method.
inline const std::vector<double> sweep_K = {10, 25, 50, 100, 200, 500, 1000};
inline const std::vector<double> sweep_D = {0, 1, 5, 20};
// [report_grid]

/// The instants of the sheets, as fractions of T (t = 0.1, 0.5, 1, 2 s for T = 2 s), and the animation frames.
inline const std::vector<double> sheet_fractions = {0.05, 0.25, 0.5, 1.0};
inline constexpr int movie_frames = 20;

/// One run: a method on the report scene with stiffness K and damping D, to t_end.
struct Run {
  std::string method;
  double K = 0, D = 0;
  double t_end = 0;
  bool figure = false;  ///< one of the runs of the figures (the cloth kept at every step) or a sweep run
  cloth::RunResult result;
};

/// What the chapter's flags set beyond the shared ones.
struct Settings {
  int threads = 2;
  bool sweep = true;
  double sweep_t_end_implicit = 0;  ///< T of implicit Euler's sweep runs
  std::string command;              ///< the reader's command line, for the page's fragment (cloth::reader_command)
};

/// The files the program writes into `--out` (figure data, tables, and each figure run's folder runs/NAME/), with
/// or without the sweep, declared once (program/output_spec.hpp).
cloth::OutputList outputs(bool sweep);

/// Refuses, before anything runs, a set of runs whose results would not fit in memory: every run's result is held
/// until the figures are written, the figures' runs with the cloth at every step, the sweep's with an energy
/// sample per step. Throws InputError naming `--t-end` (the steps) or `--grid`, whichever holds the larger share.
void require_memory_of_runs(const cloth::Options& opt, const Settings& settings);

/// Runs every run on `settings.threads` threads: first the figures' runs, run (m, c) at index
/// m * report_cases.size() + c, then the sweep, method by method, K by K, D by D. The figures' runs also leave the
/// model page's outputs in OUT/runs/METHOD_CASE/ (rk4_K50_D0).
std::vector<Run> run_all(const cloth::Options& opt, const Settings& settings);

/// The sweep run of method m at sweep_K[k], sweep_D[d].
const Run& sweep_run(const std::vector<Run>& runs, std::size_t m, std::size_t k, std::size_t d);

/// The file name of a run: "rk4_K50_D0".
std::string run_name(const Run& run);

/// The energy every ratio of the figures and tables is relative to, E_ref (see energy_reference).
struct EnergyReference {
  double joules = 0;
  bool launch = true;  ///< E(0), the launch's kinetic energy; false: the cloth starts at rest and E_ref = W L
  /// What it is, for the page: "E(0) = 79.2 kJ, the launch's kinetic energy".
  [[nodiscard]] std::string description() const;
};
/// E_ref for a scene whose energy at t = 0 is `e0` (the same for every run: K and D do not enter it).
EnergyReference energy_reference(const cloth::SceneParams& scene, double e0);

/// What the figures and tables say of a run's energy, relative to E_ref.
struct EnergyMeasures {
  double gain = 0, final_change = 0, peak = 0;
  double rise_from = 0, rise_to = 0;  ///< the stretch [s] of the largest rise, the one `gain` measures
};
EnergyMeasures energy_measures(const std::vector<cloth::EnergySample>& energy, const EnergyReference& reference);

/// The lowest free particle (positions of every particle in grid order).
double lowest_z(const cloth::Scene& scene, const cloth::Vector& positions);

/// How a run ended, for labels: "bounded", "diverged" or the failed step's kind ("newton not converged").
std::string outcome(const cloth::RunResult& r);
/// The time at which a run stopped being sane: the step after the last sane one (NaN for a finished run).
double stop_time(const cloth::RunResult& r, double h);

/// summary.dat, series_RUN.dat and mesh_RUN.dat of the figures' runs, and the tables plot.gp reads to lay
/// them out: parameters.dat, runs.dat, instants.dat, cases.dat, figures.dat.
void write_figure_data(const std::vector<Run>& runs, const cloth::Options& opt, const Settings& settings,
                       const EnergyReference& reference);

/// growth.md: explicit Euler's undamped figure runs, the energy's measured growth a step against the rest state's
/// prediction 1 + (h omega_max)^2.
void write_growth(const std::vector<Run>& runs, const cloth::Options& opt, const Settings& settings,
                  const EnergyReference& reference);

/// theory.txt, and for the page theory.md and deformed_damping.md: the stability numbers of Chapters 2-4 for every
/// (K, D), and the fastest damped mode on the deformed cloth of implicit Euler's damped runs.
void write_theory(const std::vector<Run>& runs, const cloth::Options& opt, const Settings& settings);

/// sweep.dat, and for the page sweep.md (every method's outcome and gain per K and D) and sweep_implicit.md
/// (implicit Euler's undamped runs: energy lost and lowest point).
void write_sweep(const std::vector<Run>& runs, const cloth::Options& opt, const Settings& settings,
                 const EnergyReference& reference);

}  // namespace ch05
