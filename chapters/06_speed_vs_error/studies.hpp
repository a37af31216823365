// Chapter 6's studies: where springs pass near zero length, how fast nearby solutions separate, the reference
// solution and its credentials, the work-precision sweep, and the cost of a step against the grid size.
#pragma once

#include "integrators/method_registry.hpp"
#include "model/scene.hpp"

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
  std::FILE* table = nullptr;  ///< speed_vs_error.dat
};

double max_particle_distance(const cloth::Vector& a, const cloth::Vector& b);
/// Opens DIR/name for writing and writes its header line.
std::FILE* open(const Sink& sink, const std::string& name, const char* header);

/// The spring with the smallest length relative to its rest length at positions x (`all` is scratch space for
/// every particle's position, pinned ones included).
struct ShortestSpring {
  double length_over_rest = 1e300;
  int spring = -1;
};
ShortestSpring shortest_spring(const cloth::Scene& scene, const cloth::Vector& x, cloth::Vector& all);

void near_zero_springs(const cloth::SceneParams& base, double T, double h, const Sink& sink);
void sensitivity(const cloth::SceneParams& base, const std::vector<Config>& configs, double h, const Sink& sink);
/// Returns the reference trajectory at the samples; prints and records its credentials.
Trajectory reference(const cloth::SceneParams& base, const Config& c, int samples, int k_ref, const Sink& sink,
                     double& agreement);
void work_precision(const cloth::SceneParams& base, const Config& c, const Trajectory& ref, int samples,
                    int k_min, int k_max, double max_seconds, int runs, double ref_agreement,
                    const Sink& sink);
/// Where the order of the methods goes when springs pass near zero length: RK4's local error per step along the
/// (K, D) = (50, 0) trajectory beside the shortest spring, and observed orders from successive step halvings
/// over a short and a long horizon (order_loss.cpp).
void local_error_along_trajectory(const cloth::SceneParams& base, double T, double h, const Sink& sink);
void observed_orders(const cloth::SceneParams& base, const std::vector<double>& horizons, int k_min, int k_max,
                     const Sink& sink);
/// A method stops growing the grid once a step costs more than `max_step_seconds`.
void scaling(const cloth::SceneParams& base, const std::vector<int>& sizes, int runs, double max_step_seconds,
             const Sink& sink);

}  // namespace ch06
