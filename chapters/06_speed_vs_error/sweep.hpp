// Chapter 6's work-precision sweep: the configurations, the methods under their composed names, the reference
// solution with its credentials, and the one loop that runs a method down a ladder of steps (or tolerances),
// measures its error against the reference and times it.
#pragma once

#include "integrators/configuration.hpp"
#include "model/scene.hpp"
#include "program/output.hpp"
#include "program/timing.hpp"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace ch06 {

/// One configuration of the sweep: the report scene with stiffness K and damping D, integrated to T.
struct Config {
  std::string name;
  double K = 50, D = 0, T = 1;
};

/// A trajectory sampled at t_j = j T / samples, j = 0..samples (positions of the free particles).
struct Trajectory {
  std::vector<cloth::Vector> x;
  bool ok = true;
  std::string message;
};

/// Runs `stepper` with `steps` equal steps to T (a multiple of `samples`) and samples it. Stops at the first
/// failed step or diverged state (ok = false, message says where).
Trajectory run_sampled(cloth::Stepper& stepper, double T, long long steps, int samples);

/// The methods of the sweep under their one composed name (integrators/configuration.hpp), in the order of the
/// figures: the fixed-step ones, then Chapter 8's adaptive "dopri5".
const std::vector<std::string>& sweep_methods();
/// A stepper for a fixed-step row: its configuration, with the default Newton matrix for its solver
/// (program/method_flags.hpp) unless the name chose one.
std::unique_ptr<cloth::Stepper> make_sweep_stepper(const std::string& name, cloth::ForceField& field);

/// Where the program writes: the one machine-readable table (speed_vs_error.dat) and the per-figure files.
struct Sink {
  std::string dir;
  std::FILE* table = nullptr;  ///< speed_vs_error.dat, an OutputFile the caller commits
};
/// Opens DIR/name for writing (a checked cloth::OutputFile, committed by the study when it is complete) and
/// writes its header line.
std::unique_ptr<cloth::OutputFile> open(const Sink& sink, const std::string& name, const char* header);

/// The reference's credentials: its step count and how far the 3/8 rule with twice as many steps is from it.
struct ReferenceCheck {
  std::string config;
  long long steps = 0;
  double agreement = 0;  ///< largest sampled distance between the two [m]
};
/// How far down its ladder each method goes, and how each run is timed.
struct SweepPlan {
  int k_reference = 15;      ///< the reference's steps: RK4 with h = T / 2^k_reference, the 3/8 rule with h / 2
  int samples = 16;          ///< sampled times for the RMS error (the fixed steps are 2^k, a multiple of it)
  int k_min = 4, k_max = 16;  ///< fixed steps h = T / 2^k
  int tolerance_min = 2, tolerance_max = 10;  ///< the adaptive pair's rtol = atol = 10^-j
  double max_seconds = 4;    ///< a method stops once a run takes longer; above a fifth of it, one timed run
  int runs = 5;              ///< timed runs of each point (time_runs: fastest, median, slowest)
};

/// The reference trajectory at plan.samples times; `check` receives its credentials.
Trajectory reference(const cloth::SceneParams& base, const Config& c, const SweepPlan& plan, const Sink& sink,
                     ReferenceCheck& check);

/// One run of the sweep: a fixed step h = T / steps, or (dopri5) one tolerance, with h its mean step. A run that
/// failed or whose error is within 100x of the reference's agreement is `dropped`, `why` says why.
struct WorkPoint {
  std::string config, method;
  double h = 0, tolerance = 0;
  long long steps = 0;
  cloth::Timing timing{};           ///< thread CPU seconds of one whole run to T
  double error = 0, error_rms = 0;  ///< the largest particle error at T; the RMS over the sampled times
  cloth::StepCounters counters;
  bool dropped = false;
  std::string why{};
};
/// Every method of sweep_methods() on configuration `c`, against `ref` whose credential is `ref_agreement`.
std::vector<WorkPoint> work_precision(const cloth::SceneParams& base, const Config& c, const Trajectory& ref,
                                      double ref_agreement, const SweepPlan& plan, const Sink& sink);

/// reference.md, fastest.md, fastest_summary.md, dropped.md, effective_orders.md, implicit_variants.md,
/// stiff_pick.md: what the sweep found, as the page quotes it (sweep_fragments.cpp).
void write_sweep_fragments(const std::string& dir, const std::vector<ReferenceCheck>& references,
                           const std::vector<WorkPoint>& work, const std::vector<Config>& configs,
                           const std::string& command);

}  // namespace ch06
