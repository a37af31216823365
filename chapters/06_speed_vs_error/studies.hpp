// Chapter 6's studies: where springs pass near zero length, how fast nearby solutions separate, the reference
// solution and its credentials, the work-precision sweep, and the cost of a step against the grid size.
#pragma once

#include "integrators/method_registry.hpp"
#include "model/scene.hpp"
#include "program/output.hpp"

#include <cstdio>
#include <functional>
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

/// Runs `stepper` with 2^k equal steps to T (2^k a multiple of `samples`) and samples it. Stops at the first
/// failed step or diverged state (ok = false, message says where).
Trajectory run_sampled(cloth::Stepper& stepper, double T, long long steps, int samples);

/// A row of the sweep: a method of the registry with the settings it runs with, under the label the tables and
/// figures use (the implicit rows differ only in their Newton settings).
struct SweepMethod {
  std::string label;   ///< explicit_euler, ..., implicit_euler_direct, implicit_euler_1newton_cg
  std::string method;  ///< its registry name
  cloth::MethodSettings settings;
  [[nodiscard]] std::unique_ptr<cloth::Stepper> stepper(cloth::ForceField& field) const {
    return cloth::make_stepper(method, field, settings);
  }
};
/// The rows of the work-precision sweep, in the order of its figures.
const std::vector<SweepMethod>& sweep_methods();
/// The row labelled `label`; throws InputError listing the labels when there is none.
const SweepMethod& sweep_method(const std::string& label);

/// Where the program writes: the one machine-readable table (speed_vs_error.dat) and the per-figure files.
struct Sink {
  std::string dir;
  std::FILE* table = nullptr;  ///< speed_vs_error.dat, an OutputFile the caller commits
};

double max_particle_distance(const cloth::Vector& a, const cloth::Vector& b);
/// Opens DIR/name for writing (a checked cloth::OutputFile, committed by the study when it is complete) and
/// writes its header line.
std::unique_ptr<cloth::OutputFile> open(const Sink& sink, const std::string& name, const char* header);

/// The file local_error_along_trajectory writes for step h: "local_error_h1000us.dat" for h = 1e-3 s.
std::string local_error_name(double h);

/// The spring with the smallest length relative to its rest length at positions x (`all` is scratch space for
/// every particle's position, pinned ones included).
struct ShortestSpring {
  double length_over_rest = 1e300;
  int spring = -1;
};
ShortestSpring shortest_spring(const cloth::Scene& scene, const cloth::Vector& x, cloth::Vector& all);

/// The shortest spring over time: l / L0 at every step, and where and when it was shortest.
struct NearZero {
  double h = 0;
  std::vector<double> t, shortest;  ///< at every step
  double smallest = 1e300, t_smallest = 0;
  std::string spring;  ///< "a structural spring, (9,7)-(10,7)"
};
NearZero near_zero_springs(const cloth::SceneParams& base, double T, double h, const Sink& sink);

/// Amplification of the perturbation over time, for one configuration.
struct Sensitivity {
  std::string config;
  std::vector<double> t, amplification;
};
std::vector<Sensitivity> sensitivity(const cloth::SceneParams& base, const std::vector<Config>& configs, double h,
                                     const Sink& sink);

/// The reference's credentials: its step count and how far the 3/8 rule with twice as many steps is from it.
struct ReferenceCheck {
  std::string config;
  long long steps = 0;
  double agreement = 0;  ///< largest sampled distance between the two [m]
};
/// Returns the reference trajectory at the samples; prints and records its credentials.
Trajectory reference(const cloth::SceneParams& base, const Config& c, int samples, int k_ref, const Sink& sink,
                     ReferenceCheck& check);

/// One run of the work-precision sweep: a fixed step h = T / steps, or (dopri5_adaptive) one tolerance, with h its
/// mean step. A run that failed or whose error is within 100x of the reference's agreement is `dropped`, `why`
/// says why.
struct WorkPoint {
  std::string config, method;
  double h = 0, tolerance = 0;
  long long steps = 0;
  double seconds = 0;             ///< the median wall-clock time of the whole run to T
  double error = 0, error_rms = 0;  ///< the largest particle error at T; the RMS over the sampled times
  cloth::StepCounters counters;
  bool dropped = false;
  std::string why;
};
std::vector<WorkPoint> work_precision(const cloth::SceneParams& base, const Config& c, const Trajectory& ref,
                                      int samples, int k_min, int k_max, double max_seconds, int runs,
                                      double ref_agreement, const Sink& sink);

/// Where the order of the methods goes when springs pass near zero length: RK4's local error per step along the
/// (K, D) = (50, 0) trajectory beside the shortest spring, and observed orders from successive step halvings
/// over a short and a long horizon (order_loss.cpp).
struct LocalError {
  double h = 0, jump = 0;  ///< the step, and the model's jump J = 2 K L0 / m in acceleration [m/s^2]
  long long steps = 0, jump_steps = 0;
  double worst_position = 0, worst_velocity = 0;  ///< largest local errors over the run
  double smooth_median = 0;  ///< the median local position error of the steps without a jump
};
LocalError local_error_along_trajectory(const cloth::SceneParams& base, double T, double h, const Sink& sink);
/// One step halving: the distance at T between the runs with h and h/2, and the observed order (NaN for the first).
struct ObservedOrder {
  std::string method;
  double T = 0, h = 0, difference = 0, order = 0;
};
std::vector<ObservedOrder> observed_orders(const cloth::SceneParams& base, const std::vector<double>& horizons,
                                           int k_min, int k_max, const Sink& sink);

/// One method on one grid: the cost of a step and where it goes.
struct ScalingPoint {
  std::string method;
  int size = 0, springs = 0;
  double wall_per_step = 0, cpu_per_step = 0;  ///< median seconds
  double mean_wall_per_step = 0;                ///< over every step timed, warm-up included
  double assembly_per_step = 0, factorization_per_step = 0, solve_per_step = 0;  ///< implicit steps, wall seconds
  double newton_per_step = 0, cg_per_solve = 0;
};
/// A method stops growing the grid once a step costs more than `max_step_seconds`.
std::vector<ScalingPoint> scaling(const cloth::SceneParams& base, const std::vector<int>& sizes, int runs,
                                  double max_step_seconds, const Sink& sink);

}  // namespace ch06
