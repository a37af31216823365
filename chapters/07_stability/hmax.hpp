// Chapter 7, part 3: the largest stable step h_max, predicted from the spectrum and the stability functions,
// and measured by bisection on the report scene over a log grid of K, for D = 0 and D = 20.
#pragma once

#include "cloth_spectrum.hpp"

#include <string>
#include <utility>
#include <vector>

namespace ch07 {

/// Predicted h_max: strict (every mode's growth factor at most 1) and over a horizon (no mode's energy more than
/// doubles in T).
struct Prediction {
  double strict = 0;
  double horizon = 0;
};
Prediction predict(const StabilityModel& model, const std::vector<Mode>& modes, double T, double h_cap);

/// What the sweep covers and how hard it works.
struct SweepSettings {
  std::vector<double> stiffnesses;
  std::vector<double> dampings = {0, 20};
  std::vector<std::string> methods = {"explicit_euler", "symplectic_euler", "heun", "rk4"};
  double T = 2;             ///< simulated time of every run [s]
  int bisections = 3;       ///< geometric bisections of the bracket
  double h_floor = 1e-4;    ///< smallest h tried [s]
  double h_ceiling = 0.2;   ///< largest h tried [s]
  double run_budget = 0;    ///< largest cost of one run in unknowns x right-hand sides (0: no limit)
  bool dense_implicit = false;  ///< also probe implicit Euler at h = 0.01, not only at 0.1
  int threads = 2;
};

/// predicted_rest.dat: the rest-state prediction of every method, 4 points per decade of K (no simulation).
void write_rest_predictions(const std::string& dir, const RestSpectrum& rest, const SweepSettings& sweep, double m);

/// predicted.dat, measured.dat and implicit_euler.txt: predictions at the rest state and at the sagged
/// equilibrium, and the measured bracket of h_max, for every K, D and method of the sweep; hmax_table.md, the
/// book's table of them, measured by `command`. Returns summary entries.
std::vector<std::pair<std::string, std::string>> hmax_sweep(const std::string& dir, const cloth::SceneParams& scene,
                                                            const RestSpectrum& rest, Equilibria& equilibria,
                                                            const SweepSettings& sweep, const std::string& command);

}  // namespace ch07
