// Chapter 10: how sensitive the curtain's motion is, and what that does to a method's error. The growth of a small
// perturbation of the released sheet, followed by two tight Dormand-Prince references, and symplectic Euler's and
// RK4's errors over time as their step is halved: where each error still scales with its step, and where it has
// left the linear regime of the perturbation's growth.
#include "analysis/reference_trajectory.hpp"
#include "analysis/trajectory_measures.hpp"
#include "integrators/method_registry.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/timing.hpp"
#include "study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

using namespace cloth;
using ch10::format;

namespace {

constexpr double T = 0.6;        // the curtain's horizon (Cloth that moves)
constexpr int frames = 36;       // 1/60 s apart
constexpr int frames_per_column = 6;  // the tables print every 0.1 s

// The curtain of Cloth that moves: the chapter's fabric at K = 1e5 N/m hung by one edge, released from flat.
SceneParams curtain() {
  SceneParams p = ch10::fabric(20, 1e5);
  p.pins = PinSet::edge;
  return p;
}

// [perturbation]
// A fixed pseudo-random direction: every coordinate of every free particle drawn uniformly from [-1, 1] (a 64-bit
// linear congruential generator, so that every build draws the same numbers), scaled so that the particle moved
// farthest moves by exactly 1 m. The perturbed start is x0 + epsilon times it.
Vector perturbation_direction(Eigen::Index dofs) {
  Vector d(dofs);
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  for (Eigen::Index i = 0; i < dofs; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    d[i] = 2.0 * static_cast<double>(state >> 11) / 9007199254740992.0 - 1.0;  // 53 bits into [-1, 1)
  }
  return d / largest_distance(d, Vector::Zero(dofs));
}
// [perturbation]

// The largest distance between two recorded motions at every frame.
std::vector<double> distances(const ReferenceTrajectory& a, const ReferenceTrajectory& b) {
  std::vector<double> d;
  for (int k = 0; k <= frames; ++k) d.push_back(largest_distance(a.frames[k].positions, b.frames[k].positions));
  return d;
}

std::vector<std::string> time_header(const std::string& first) {
  std::vector<std::string> header = {first};
  for (int k = frames_per_column; k <= frames; k += frames_per_column)
    header.push_back(format("t = %.1f s", k * T / frames));
  return header;
}

struct Growth {
  double epsilon;
  std::vector<double> distance;  // at every frame
};

// (1) The growth factor: the perturbed curtain against the unperturbed one, both by Dormand-Prince at `tolerance`.
// In the linear regime distance / epsilon is one number G(t) for every epsilon; where it falls below the smallest
// epsilon's, the perturbation has saturated.
void growth_table(const std::string& out, const std::string& command, const Scene& scene, ForceField& field,
                  const ReferenceTrajectory& truth, double tolerance, const std::vector<double>& epsilons,
                  std::string& dat) {
  const Vector direction = perturbation_direction(scene.dof_count());
  std::vector<Growth> runs;
  // The reference's own error, amplified like any perturbation: the same curtain at a tolerance 100 times looser.
  const ReferenceTrajectory looser = reference_trajectory(field, scene.initial_positions(), scene.initial_velocities(),
                                                          T, frames, 100 * tolerance, &interrupt_flag());
  throw_if_interrupted();
  for (const double epsilon : epsilons) {
    const Vector x0 = scene.initial_positions() + epsilon * direction;
    const ReferenceTrajectory perturbed =
        reference_trajectory(field, x0, scene.initial_velocities(), T, frames, tolerance, &interrupt_flag());
    throw_if_interrupted();
    runs.push_back({epsilon, distances(perturbed, truth)});
  }
  MarkdownTable t(time_header("ε [m]: growth (distance [m])"), std::string(frames / frames_per_column + 1, 'r'));
  const std::vector<double> floor = distances(looser, truth);
  std::vector<std::string> row = {format("the reference at %.0e against %.0e", 100 * tolerance, tolerance)};
  for (int k = frames_per_column; k <= frames; k += frames_per_column) row.push_back(format("%.1e", floor[k]));
  t.add_row(row);
  dat += "# growth: epsilon, then t and largest distance / epsilon at every frame\n";
  for (const Growth& g : runs) {
    row = {format("%.0e", g.epsilon)};
    for (int k = frames_per_column; k <= frames; k += frames_per_column)
      row.push_back(format("%.2g (%.1e)", g.distance[k] / g.epsilon, g.distance[k]));
    t.add_row(row);
    for (int k = 0; k <= frames; ++k)
      dat += format("%.0e %.6f %.6e\n", g.epsilon, k * T / frames, g.distance[k] / g.epsilon);
  }
  // The largest distance still in the linear regime: the largest perturbation grown to within 20 % of the
  // smallest epsilon's growth factor (the smallest taken as linear; the reference row says how far above its floor
  // it lies).
  row = {"largest distance growing within 20 % of the smallest ε's factor"};
  for (int k = frames_per_column; k <= frames; k += frames_per_column) {
    const double linear = runs.front().distance[k] / runs.front().epsilon;
    double largest = 0;
    for (const Growth& g : runs)
      if (std::abs(g.distance[k] / g.epsilon / linear - 1) <= 0.2) largest = std::max(largest, g.distance[k]);
    row.push_back(format("%.1e", largest));
  }
  t.add_row(row);
  write_table_fragment(out + "/sensitivity_growth.md", t, command);
}

struct MethodRun {
  std::string method;
  int steps_per_frame;
  std::vector<double> error;  // at every frame
  double shortest = std::numeric_limits<double>::infinity();  // shortest spring over every step, l / L0
};

// A run of `method` over the frames, its error against `truth` at each, and the shortest spring at every step
// (does it ever come near the guard at degenerate_length_fraction of its rest length?).
MethodRun method_run(const Scene& scene, ForceField& field, const ReferenceTrajectory& truth, const std::string& method,
                     int steps_per_frame) {
  MethodRun r{method, steps_per_frame, {0.0}};
  const auto stepper = make_stepper(method, field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  Vector all(3 * scene.particle_count());
  const double h = T / frames / steps_per_frame;
  for (int k = 1; k <= frames; ++k) {
    for (int s = 0; s < steps_per_frame; ++s) {
      stepper->step(h, x, v);
      scene.all_positions(x, all);
      for (const Spring& spring : scene.springs().springs) {
        const int p = scene.particle_of_slot(spring.p), q = scene.particle_of_slot(spring.q);
        r.shortest = std::min(r.shortest, (all.segment<3>(3 * p) - all.segment<3>(3 * q)).norm() / spring.rest_length);
      }
    }
    throw_if_interrupted();
    r.error.push_back(largest_distance(all, truth.frames[k].positions));  // frames hold every particle
  }
  return r;
}

// (2) The methods' errors over time as the step is halved, with the ratio to the error at twice the step: 2 for a
// first-order error, 16 for a fourth-order one, while the error is in the linear regime.
void method_table(const std::string& out, const std::string& command, const Scene& scene, ForceField& field,
                  const ReferenceTrajectory& truth, std::string& dat) {
  MarkdownTable t(time_header("method, h [s]"), std::string("l").append(frames / frames_per_column, 'r'));
  double shortest = std::numeric_limits<double>::infinity();
  dat += "# methods: method, steps per frame, t, largest distance from the reference\n";
  for (const std::string method : {"symplectic_euler", "rk4"}) {
    const MethodRun* previous = nullptr;
    std::vector<MethodRun> runs;
    runs.reserve(3);
    for (const int n : {354, 708, 1416}) {  // h = 1/21240, 1/42480, 1/84960 s: below both stable steps
      runs.push_back(method_run(scene, field, truth, method, n));
      const MethodRun& r = runs.back();
      shortest = std::min(shortest, r.shortest);
      std::vector<std::string> row = {format("`%s`, 1/%d", method.c_str(), 60 * n)};
      for (int k = frames_per_column; k <= frames; k += frames_per_column)
        row.push_back(previous == nullptr ? format("%.1e", r.error[k])
                                          : format("%.1e (%.2g)", r.error[k], previous->error[k] / r.error[k]));
      t.add_row(row);
      for (int k = 0; k <= frames; ++k)
        dat += format("%s %d %.6f %.6e\n", method.c_str(), n, k * T / frames, r.error[k]);
      previous = &r;
    }
  }
  write_table_fragment(out + "/sensitivity_methods.md", t, command);
  write_text_fragment(out + "/sensitivity_guard.md",
                      format("Over every step of the six runs above the shortest spring was %.4f of its rest length, "
                             "against the guard's %.0e.\n",
                             shortest, degenerate_length_fraction));
}

// The page shows the full run's tables, committed under data/sensitivity_full: the quick run's are data.
const OutputList sensitivity_outputs = {
    {"sensitivity_growth.md", OutputKind::data, "a perturbation's growth over time, for each size of it"},
    {"sensitivity_methods.md", OutputKind::data, "symplectic Euler's and RK4's errors over time as h is halved"},
    {"sensitivity_guard.md", OutputKind::data, "the shortest spring of the reference against the guard's length"},
    {"sensitivity.dat", OutputKind::data, "the growth and the errors of the tables at every frame"}};

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch10_sensitivity",
                  "Chapter 10: the growth of a perturbation of the curtain released from flat, and symplectic Euler's\n"
                  "and RK4's errors over time as their step is halved.");
  cli.use_common({"--out"});
  bool quick = false;
  cli.add_switch("--quick", "references at 1e-9 and two perturbations instead of 1e-12 and nine",
                 [&] { quick = true; });
  cli.declare_outputs([](const Options&) { return sensitivity_outputs; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const std::string out = opt.run.out_dir;
    prepare_declared_outputs(out, sensitivity_outputs);
    const std::string command = reader_command(argc, argv);
    const Scene scene(curtain());
    ForceField field(scene);
    const double tolerance = quick ? 1e-9 : 1e-12;
    const double started = thread_cpu_seconds();
    const ReferenceTrajectory truth = reference_trajectory(field, scene.initial_positions(),
                                                           scene.initial_velocities(), T, frames, tolerance,
                                                           &interrupt_flag());
    throw_if_interrupted();
    std::printf("reference at %.0e: %lld steps, %.2f s CPU\n", tolerance, truth.steps, thread_cpu_seconds() - started);
    std::string dat;
    growth_table(out, command, scene, field, truth, tolerance,
                 quick ? std::vector<double>{1e-8, 1e-5}
                       : std::vector<double>{1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4},
                 dat);
    method_table(out, command, scene, field, truth, dat);
    ch10::write_text(out, "sensitivity.dat", dat);
    return 0;
  });
}
