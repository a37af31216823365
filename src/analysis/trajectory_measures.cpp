// Measures of a motion against a reference motion (see trajectory_measures.hpp).
#include "analysis/trajectory_measures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace cloth {

double largest_distance(const Vector& a, const Vector& b) {
  if (a.size() != b.size()) throw std::invalid_argument("largest_distance: the two states differ in size");
  double worst = 0;
  for (Eigen::Index k = 0; k + 2 < a.size(); k += 3) worst = std::max(worst, (a.segment<3>(k) - b.segment<3>(k)).norm());
  return worst;
}

TrajectoryError trajectory_error(const std::vector<Frame>& run, const std::vector<Frame>& reference) {
  if (run.empty() || reference.empty()) throw std::invalid_argument("trajectory_error: no frames");
  const auto same_time = [](double a, double b) { return std::abs(a - b) <= 1e-9; };
  if (!same_time(run.back().t, reference.back().t))
    throw std::invalid_argument("trajectory_error: the run ends at a different time than the reference");
  TrajectoryError e;
  std::size_t r = 0;  // both are in time order: one pass
  for (const Frame& frame : run) {
    while (r < reference.size() && reference[r].t < frame.t - 1e-9) ++r;
    if (r == reference.size() || !same_time(reference[r].t, frame.t))
      throw std::invalid_argument("trajectory_error: the reference has no frame at a time of the run");
    const double distance = largest_distance(frame.positions, reference[r].positions);
    if (distance > e.over_frames) e.over_frames = distance, e.worst_time = frame.t;
  }
  e.at_end = largest_distance(run.back().positions, reference.back().positions);
  return e;
}

TrajectoryError motion_size(const std::vector<Frame>& reference) {
  if (reference.empty()) throw std::invalid_argument("motion_size: no frames");
  std::vector<Frame> still = reference;
  for (Frame& frame : still) frame.positions = reference.front().positions;
  return trajectory_error(still, reference);
}

double largest_strain(const Scene& scene, const Vector& positions) {
  double worst = 0;
  for (const Spring& s : scene.springs().springs) {
    const int p = scene.particle_of_slot(s.p), q = scene.particle_of_slot(s.q);
    const double l = (positions.segment<3>(3 * p) - positions.segment<3>(3 * q)).norm();
    worst = std::max(worst, std::abs(l / s.rest_length - 1));
  }
  return worst;
}

double largest_strain(const Scene& scene, const std::vector<Frame>& frames) {
  double worst = 0;
  for (const Frame& frame : frames) worst = std::max(worst, largest_strain(scene, frame.positions));
  return worst;
}

std::vector<double> free_edge_height(const Grid& grid, const std::vector<Frame>& frames) {
  std::vector<double> height;
  height.reserve(frames.size());
  for (const Frame& frame : frames) {
    double sum = 0;
    for (int i = 0; i < grid.M; ++i) sum += frame.positions[3 * grid.particle(i, 0) + 2];
    height.push_back(sum / grid.M);
  }
  return height;
}

double first_minimum_time(const std::vector<double>& t, const std::vector<double>& y) {
  if (t.size() != y.size()) throw std::invalid_argument("first_minimum_time: t and y differ in length");
  for (std::size_t k = 1; k + 1 < y.size(); ++k) {
    if (!(y[k - 1] > y[k] && y[k] <= y[k + 1])) continue;
    // The parabola through the three samples in Newton's form, p(s) = y_{k-1} + d1 (s - t_{k-1}) + d2 (s - t_{k-1})
    // (s - t_k) with the divided differences d1 = y[t_{k-1}, t_k] and d2 = y[t_{k-1}, t_k, t_{k+1}]: its vertex is
    // where p'(s) = d1 + d2 (2 s - t_{k-1} - t_k) vanishes.
    const double d1 = (y[k] - y[k - 1]) / (t[k] - t[k - 1]);
    const double d2 = ((y[k + 1] - y[k]) / (t[k + 1] - t[k]) - d1) / (t[k + 1] - t[k - 1]);
    if (!(d2 > 0)) return t[k];  // a flat bottom: the sample itself
    return 0.5 * (t[k] + t[k - 1]) - d1 / (2 * d2);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

EnergyLoss energy_lost(const Energy& run, const Energy& reference, double scale) {
  const double joules = reference.total() - run.total();
  return {joules, joules / scale};
}

AccuracyVerdict accuracy_verdict(double error, double motion, double level) {
  if (level >= motion) return AccuracyVerdict::met_by_rest;
  return error <= level ? AccuracyVerdict::reached : AccuracyVerdict::missed;
}

const char* accuracy_verdict_name(AccuracyVerdict verdict) {
  switch (verdict) {
    case AccuracyVerdict::reached: return "reached";
    case AccuracyVerdict::missed: return "missed";
    case AccuracyVerdict::met_by_rest: return "met by standing still";
  }
  return "?";
}

std::string met_by_standing_still(double motion) {
  char text[96];
  std::snprintf(text, sizeof text, "met by standing still (the rest state is %.3g m from the reference)", motion);
  return text;
}

int fastest_reaching(const std::vector<RunCost>& runs, double motion, double level) {
  int best = -1;
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (accuracy_verdict(runs[k].error, motion, level) == AccuracyVerdict::reached &&
        (best < 0 || runs[k].seconds < runs[static_cast<std::size_t>(best)].seconds))
      best = static_cast<int>(k);
  return best;
}

}  // namespace cloth
