// Chapter 12's measurements of what bending costs: one evaluation of each term beside the springs' (cost.md), and
// the fastest bending mode against the springs' as the spacing halves, the explicit step each allows
// (stable_step.md).
#include "report.hpp"

#include "analysis/power_iteration.hpp"
#include "base/format_number.hpp"
#include "model/bending.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// The median of `samples` with the smallest and largest beside it, each times `scale` to `decimals` decimals.
std::string spread_cell(std::vector<double> samples, double scale, int decimals) {
  std::sort(samples.begin(), samples.end());
  std::string cell = format_fixed(scale * samples[samples.size() / 2], decimals);
  cell += " (";
  cell += format_fixed(scale * samples.front(), decimals);
  cell += '-';
  cell += format_fixed(scale * samples.back(), decimals);
  cell += ')';
  return cell;
}

}  // namespace

std::string milliseconds_cell(const std::function<void()>& work) {
  const Timing t = time_runs(work, {.runs = 5, .repeat = 5});
  return spread_cell({t.fastest_cpu, t.median_cpu, t.slowest_cpu}, 1e3, 3);
}

// cost.md: the time of one force evaluation and one Hessian of the springs and of each bending model, on a
// 60 x 60 sheet bent slightly at random (the median of 5 repetitions of 5 evaluations each, with their spread);
// then the dihedral angles' Hessians in closed form and by forward mode, timed alternately, and their ratio.
void write_cost(const std::string& dir, const std::string& command) {
  SceneParams sp;
  sp.grid = Grid{60, 60, 0.01};
  sp.pins = PinSet::none;
  sp.gravity = 0;
  const Scene scene(sp);
  ForceField springs(scene);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  Vector x = scene.initial_positions(), v = Vector::Zero(scene.dof_count()), f(scene.dof_count());
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] += 0.05 * sp.grid.d * unit(rng);
  MarkdownTable table({"term (60 x 60 sheet)", "elements", "forces [ms]: median (fastest-slowest)",
                       "Hessian [ms]: median (fastest-slowest)"}, "lrrr");
  SparseMatrix dfdx = springs.pattern(), dfdv = springs.pattern();
  table.add_row({"springs (structural, shear, flexion)", std::to_string(scene.springs().size()),
                 milliseconds_cell([&] { springs.forces(x, v, f); }),
                 milliseconds_cell([&] { springs.jacobians(x, v, dfdx, dfdv); })});
  for (const BendingModel model : {BendingModel::hinge, BendingModel::quadratic}) {
    BendingEnergy bending(scene, model, 1e-5);
    bending.hessian(x, false);  // the pattern, once
    table.add_row({std::string(bending_models().name(model)) + " bending", std::to_string(bending.hinges().size()),
                   milliseconds_cell([&] { bending.add_forces(x, f); }),
                   milliseconds_cell([&] { bending.hessian(x, false); })});
  }
  // The dihedral angles' Hessians alone, in closed form and by forward-mode differentiation (model/bending.hpp).
  const BendingEnergy hinges(scene, BendingModel::hinge, 1e-5);
  const auto all_angle_hessians = [&](Matrix12 (*hessian)(const Vector12&)) {
    Matrix12 sum = Matrix12::Zero();
    for (const Hinge& h : hinges.hinges()) {
      Vector12 y;  // no particle is pinned: slots are particles
      for (int k = 0; k < 4; ++k) y.segment<3>(3 * k) = x.segment<3>(3 * h.particle[static_cast<std::size_t>(k)]);
      sum += hessian(y);
    }
    return sum;
  };
  volatile double sink = 0;  // keeps the unused sums from being optimised away
  // The two alternate, run by run, so that both see the same load of a shared machine; their ratio is taken per
  // pair of neighbouring runs.
  std::vector<double> closed, forward, ratio;
  for (int run = 0; run < 7; ++run) {
    throw_if_interrupted();
    closed.push_back(time_runs([&] { sink = all_angle_hessians(&hinge_angle_hessian).sum(); },
                               {.runs = 1, .repeat = 5}).median_cpu);
    forward.push_back(time_runs([&] { sink = all_angle_hessians(&hinge_angle_hessian_forward_mode).sum(); },
                                {.runs = 1, .repeat = 5}).median_cpu);
    ratio.push_back(forward.back() / closed.back());
  }
  const std::string count = std::to_string(hinges.hinges().size());
  table.add_row({"d^2 theta of every hinge, closed form", count, "", spread_cell(closed, 1e3, 3)});
  table.add_row({"d^2 theta of every hinge, forward mode", count, "", spread_cell(forward, 1e3, 3)});
  table.add_row({"forward mode / closed form, alternated runs", "", "", spread_cell(ratio, 1, 2)});
  write_table_fragment(dir + "/cost.md", table, command);
}

// stable_step.md: the fastest mode of the bending energy against the springs' on a free 24 x 24 sheet of fabric
// (rho_A = 0.2 kg/m^2, B = 5e-6 N m, structural and shear springs of K = 1e4 N/m), as the spacing halves: the
// largest eigenvalue omega^2 of M^{-1} times each Hessian at rest, by power iteration, beside the chain's
// 16 B / (rho_A d^4), and the explicit step 2 / omega each allows (symplectic Euler's limit).
void write_stable_step(const std::string& dir, const std::string& command) {
  const double rho = 0.2, B = 5e-6;
  MarkdownTable table({"spacing d [mm]", "springs: omega^2 [1/s^2]", "quadratic bending: omega^2 [1/s^2]",
                       "16 B / (rho_A d^4)", "h limit, springs [s]", "h limit, bending [s]"}, "rrrrrr");
  for (const double d : {0.01, 0.005, 0.0025, 0.00125}) {
    throw_if_interrupted();
    SceneParams sp;
    sp.grid = Grid{24, 24, d};
    sp.pins = PinSet::none;
    sp.gravity = 0;
    sp.stiffness = 1e4;
    sp.families.on[static_cast<int>(SpringFamily::flexion)] = false;
    sp.mass = rho * d * d;
    const Scene scene(sp);
    ForceField springs(scene);
    SparseMatrix dfdx = springs.pattern(), dfdv = springs.pattern();
    const Vector x = scene.initial_positions(), v = Vector::Zero(scene.dof_count());
    springs.jacobians(x, v, dfdx, dfdv);
    BendingEnergy bending(scene, BendingModel::quadratic, B);
    const SparseMatrix H = bending.hessian(x, false);
    // A start vector with every mode in it: pseudo-random, fixed.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    Vector y0(scene.dof_count());
    for (Eigen::Index k = 0; k < y0.size(); ++k) y0[k] = unit(rng);
    PowerIterationSettings settings;
    settings.tolerance = 1e-9;
    settings.max_iterations = 20000;
    const double w2_springs = dominant_eigenvalue([&](const Vector& y, Vector& out) { out = -(dfdx * y) / sp.mass; },
                                              y0, settings).magnitude;
    const double w2_bending = dominant_eigenvalue([&](const Vector& y, Vector& out) { out = (H * y) / sp.mass; },
                                              y0, settings).magnitude;
    table.add_row({format_number(1e3 * d, 3), format_significant(w2_springs, 3), format_significant(w2_bending, 3),
                   format_significant(16 * B / (rho * d * d * d * d), 3),
                   format_significant(2 / std::sqrt(w2_springs), 3), format_significant(2 / std::sqrt(w2_bending), 3)});
  }
  write_table_fragment(dir + "/stable_step.md", table, command);
}

