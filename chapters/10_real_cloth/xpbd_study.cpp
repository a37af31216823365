// Chapter 10: how XPBD relates to implicit Euler, measured. From a moving curtain, many XPBD iterations against
// Newton's implicit Euler step of the same h, as a function of h and K, beside the gap its dropped term predicts
// (integrators/xpbd.cpp); and on the curtain released from flat, the stretch XPBD and small steps let through.
#include "analysis/spring_strain.hpp"
#include "base/format_number.hpp"
#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/xpbd.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "study.hpp"

#include "analysis/trajectory_measures.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// The chapter's fabric (20 x 20 particles 5 cm apart, 0.625 g each, D = 0.01) hung by one edge, released from
// flat at rest: the curtain.
SceneParams curtain(double K) {
  SceneParams p = ch10::fabric(20, K);
  p.pins = PinSet::edge;
  return p;
}

// A step at which explicit methods are stable with room to spare: each particle has at most 12 springs, so the
// largest eigenvalue of L = sum u u^T is at most 24 (twice the largest degree), omega_max <= sqrt(24 K / m), and
// this step gives h omega_max <= 1.
double safe_explicit_step(const SceneParams& p) { return 1.0 / std::sqrt(24 * p.stiffness / p.mass); }

struct State {
  Vector x, v;
};

// The curtain at time t, by RK4 at the safe step (its error there is far below every gap measured here).
State curtain_at(const Scene& scene, double t, std::vector<double>* strain = nullptr) {
  ForceField field(scene);
  const auto rk4 = make_stepper("rk4", field);
  State s{scene.initial_positions(), scene.initial_velocities()};
  const auto steps = static_cast<long long>(std::ceil(t / safe_explicit_step(scene.params())));
  Vector all(3 * scene.particle_count());
  for (long long k = 0; k < steps; ++k) {
    rk4->step(t / static_cast<double>(steps), s.x, s.v);
    if (strain != nullptr) {
      scene.all_positions(s.x, all);
      strain->push_back(largest_spring_strain(scene, all));
    }
  }
  return s;
}

// Converged XPBD against Newton's implicit Euler step of h from `start`: the step's size, the gap, the gap that
// A^-1 r predicts (r implicit Euler's residual at XPBD's answer), and how settled XPBD's answer was.
std::vector<std::string> gap_row(const Scene& scene, const State& start, double h) {
  const SceneParams& p = scene.params();
  ForceField field(scene);
  // Tight enough that Newton's own error (about h tol (1 + |v|) in position) is far below every gap measured, and
  // no tighter: on 0.625 g particles the residual test tol m (1 + |v|) is then at its rounding floor.
  NewtonSettings tight;
  tight.tolerance = 1e-9;
  tight.max_iterations = 100;
  ImplicitEuler newton(field, tight);
  State ie = start;
  const std::vector<std::string> head = {format_number(p.stiffness), "1/" + format_number(1 / h, 4),
                                         format_number(h * h * p.stiffness / p.mass, 2)};
  if (!newton.step(h, ie.x, ie.v)) {
    std::vector<std::string> row = head;
    row.insert(row.end(), {"Newton: " + newton.failure().reason, "", "", "", ""});
    return row;
  }
  // Sweeps doubled until doubling them moves XPBD's answer by less than a hundredth of the gap, or 32768 sweeps.
  MethodSettings settings;
  State xpbd, previous;
  double gap = 0, change = INFINITY;
  for (int sweeps = 64; sweeps <= 32768 && !(change < 1e-2 * gap); sweeps *= 2) {
    settings.xpbd_iterations = sweeps;
    xpbd = start;
    make_stepper("xpbd", field, settings)->step(h, xpbd.x, xpbd.v);
    throw_if_interrupted();
    if (previous.x.size() != 0) change = largest_distance(xpbd.x, previous.x);
    gap = largest_distance(xpbd.x, ie.x);
    previous = xpbd;
  }
  Vector f(xpbd.x.size());
  field.forces(xpbd.x, xpbd.v, f);
  const Vector r = p.mass * (xpbd.x - start.x - h * start.v) - h * h * f;
  SparseMatrix A = field.pattern();
  field.newton_matrix(xpbd.x, xpbd.v, h, StiffnessTreatment::exact, A);
  const Eigen::SparseLU<SparseMatrix> lu(A);
  const Vector predicted = lu.solve(r);
  std::vector<std::string> row = head;
  row.insert(row.end(), {format_number(largest_distance(ie.x, start.x), 3), format_number(gap, 3),
                         format_number(largest_distance(predicted, Vector::Zero(predicted.size())), 3),
                         format_number(largest_distance(xpbd.x - ie.x, predicted), 2),
                         std::to_string(settings.xpbd_iterations) + " (" + format_number(change, 2) + ")" +
                             (change < 1e-2 * gap ? "" : ": not settled")});
  return row;
}

void gap_table(const std::string& dir, const std::string& command) {
  MarkdownTable table({"K [N/m]", "h [s]", "h^2 K / m", "implicit Euler's step [m]", "XPBD - implicit Euler [m]",
                       "predicted A^-1 r [m]", "gap - prediction [m]", "XPBD sweeps (change at the last doubling [m])"},
                      "rrrrrrrr");
  for (const double K : {1e3, 1e4, 1e5}) {
    const Scene scene(curtain(K));
    const State start = curtain_at(scene, 0.1);  // moving: 0.1 s after its release
    for (const double h : {1.0 / 60, 1.0 / 240, 1.0 / 960}) table.add_row(gap_row(scene, start, h));
  }
  write_table_fragment(dir + "/xpbd_gap.md", table, command);
}

// The largest strain over every step, and the largest position difference from `reference` at T, of a
// position-based method on the curtain released from flat.
std::vector<std::string> strain_row(const Scene& scene, const std::string& method, int iterations, int substeps,
                                    double h, double T, const Vector& reference) {
  ForceField field(scene);
  MethodSettings settings;
  settings.xpbd_iterations = iterations;
  settings.substeps = substeps;
  const auto stepper = make_stepper(method, field, settings);
  State s{scene.initial_positions(), scene.initial_velocities()};
  Vector all(3 * scene.particle_count());
  double strain = 0;
  for (long long k = 0; k < std::llround(T / h); ++k) {
    stepper->step(h, s.x, s.v);
    scene.all_positions(s.x, all);
    strain = std::max(strain, largest_spring_strain(scene, all));
  }
  throw_if_interrupted();
  return {"`" + method + "`", std::to_string(iterations), std::to_string(substeps),
          std::to_string(iterations * substeps), format_number(100 * strain, 3) + " %",
          format_number(largest_distance(s.x, reference), 3)};
}

void strain_table(const std::string& dir, const std::string& command) {
  const double h = 1.0 / 60, T = 0.5;
  const Scene scene(curtain(1e5));
  std::vector<double> strains;
  const State truth = curtain_at(scene, T, &strains);
  const double motion = largest_distance(truth.x, scene.initial_positions());
  MarkdownTable table({"method", "iterations", "substeps per 1/60 s", "sweeps per 1/60 s", "largest strain",
                       "largest position difference at T [m]"},
                      "lrrrrr");
  table.add_row({"the spring model (RK4 at h = " + format_number(safe_explicit_step(scene.params()), 2) + " s)", "",
                 "", "", format_number(100 * *std::max_element(strains.begin(), strains.end()), 3) + " %",
                 "the motion: " + format_number(motion, 3)});
  for (const int n : {1, 4, 16, 64}) table.add_row(strain_row(scene, "xpbd", n, 1, h, T, truth.x));
  for (const int n : {4, 16, 64, 256}) table.add_row(strain_row(scene, "small_steps", 1, n, h, T, truth.x));
  write_table_fragment(dir + "/xpbd_strain.md", table, command);
}

const OutputList xpbd_outputs = {
    {"xpbd_gap.md", OutputKind::fragment, "XPBD's converged step against implicit Euler's, over K and h"},
    {"xpbd_strain.md", OutputKind::fragment, "the stretch XPBD and small steps let through on the curtain"}};

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch10_xpbd",
                  "Chapter 10: XPBD's converged step against implicit Euler's on the moving curtain (K and h), and\n"
                  "the stretch XPBD and small steps let through on the curtain released from flat.");
  cli.use_common({"--out"});
  cli.declare_outputs([](const Options&) { return xpbd_outputs; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    prepare_declared_outputs(opt.run.out_dir, xpbd_outputs);
    const std::string command = reader_command(argc, argv);
    gap_table(opt.run.out_dir, command);
    strain_table(opt.run.out_dir, command);
    return 0;
  });
}
