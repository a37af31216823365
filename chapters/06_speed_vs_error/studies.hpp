// Chapter 6's studies of where the scene is hard and what a step costs: springs passing near zero length
// (near_zero.cpp), what that does to the orders (order_loss.cpp), how fast nearby solutions separate
// (sensitivity.cpp), and the cost of a step against the grid size (scaling.cpp). Each study writes its data
// files while it runs and its fragments of the page afterwards.
#pragma once

#include "sweep.hpp"

#include <string>
#include <vector>

namespace ch06 {

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
/// near_zero.md: when the shortest spring first comes near zero length, and how often.
void write_near_zero_fragment(const std::string& dir, const NearZero& nz);

/// Amplification of the perturbation over time, for one configuration.
struct Sensitivity {
  std::string config;
  std::vector<double> t, amplification;
};
std::vector<Sensitivity> sensitivity(const cloth::SceneParams& base, const std::vector<Config>& configs, double h,
                                     const Sink& sink);
/// sensitivity.md: how much each configuration amplifies a perturbation, and when.
void write_sensitivity_fragment(const std::string& dir, const std::vector<Sensitivity>& s,
                                const std::vector<Config>& configs, const std::string& command);

/// The file local_error_along_trajectory writes for step h: "local_error_h1000us.dat" for h = 1e-3 s.
std::string local_error_name(double h);
/// RK4's local error per step along the (K, D) = (50, 0) trajectory beside the shortest spring.
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
/// The step halvings of the observed orders: h = T / 2^k for k = k_min .. k_max, at each horizon T.
struct OrderLadder {
  std::vector<double> horizons;  ///< T [s]
  int k_min = 6, k_max = 15;
};
std::vector<ObservedOrder> observed_orders(const cloth::SceneParams& base, const OrderLadder& ladder,
                                           const Sink& sink);
/// jumps.md, local_error.md and observed_orders.md.
void write_order_loss_fragments(const std::string& dir, const std::vector<LocalError>& local_errors,
                                const std::vector<ObservedOrder>& orders, const std::string& command);

/// One method on one grid: the cost of a step and where it goes.
struct ScalingPoint {
  std::string method;
  int size = 0, springs = 0;
  double wall_per_step = 0;                     ///< median seconds
  double cpu_per_step = 0;                      ///< fastest thread CPU seconds
  double mean_wall_per_step = 0;                ///< over every step timed, warm-up included
  double assembly_per_step = 0, factorization_per_step = 0, solve_per_step = 0;  ///< implicit steps, wall seconds
  double newton_per_step = 0, cg_per_solve = 0;
};
/// How far the grid grows and how each size is timed.
struct ScalingPlan {
  std::vector<int> sizes;          ///< M = N
  int runs = 5;                    ///< timed runs per size
  double max_step_seconds = 2;     ///< a method stops growing the grid once a step costs more
};
std::vector<ScalingPoint> scaling(const cloth::SceneParams& base, const ScalingPlan& plan, const Sink& sink);
/// scaling.md: the cost of a step per grid, with fitted exponents.
void write_scaling_fragment(const std::string& dir, const std::vector<ScalingPoint>& scaling,
                            const std::string& command);

}  // namespace ch06
