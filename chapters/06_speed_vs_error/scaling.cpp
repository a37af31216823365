// Chapter 6: the cost of one step against the grid size, for an explicit and an implicit method each with its
// usual step, and where an implicit step's time goes (assembly, factorization, solve).
#include "page_text.hpp"
#include "studies.hpp"

#include "integrators/implicit_euler.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace ch06 {

using namespace cloth;

namespace {

const std::vector<std::string> scaling_methods = {"explicit_euler", "rk4", "implicit_euler", "implicit_euler/cg"};

// A grid size of the scaling study, kept: its line in scaling.dat and speed_vs_error.dat, and on the console.
void record(const Sink& sink, std::FILE* f, const ScalingPoint& p, double h) {
  std::fprintf(f, "%s %d %d %.6e %.6e %.6e %.6e %.3f %.2f %.6e\n", p.method.c_str(), p.size, p.springs,
               p.wall_per_step, p.assembly_per_step, p.factorization_per_step, p.solve_per_step, p.newton_per_step,
               p.cg_per_solve, p.cpu_per_step);
  std::fprintf(sink.table, "scaling %dx%d %s %.6g %d %.6e - - - - - - - ok\n", p.size, p.size, p.method.c_str(), h,
               p.springs, p.wall_per_step);
  std::fflush(f);
  std::printf("scaling %-20s %4dx%-4d %8d springs %10.3f ms/step (assembly %.3f, factorization %.3f, solve "
              "%.3f ms), %.2f Newton/step, %.1f CG/solve\n",
              p.method.c_str(), p.size, p.size, p.springs, 1e3 * p.wall_per_step, 1e3 * p.assembly_per_step,
              1e3 * p.factorization_per_step, 1e3 * p.solve_per_step, p.newton_per_step, p.cg_per_solve);
}

}  // namespace

// [scaling]
// Cost of one step against the grid size, at the report's h = 0.01 for the implicit methods and h = 1e-3 for
// the explicit ones (the step changes the work per step only through Newton and CG iteration counts).
std::vector<ScalingPoint> scaling(const SceneParams& base, const ScalingPlan& plan, const Sink& sink) {
  const auto file = open(sink, "scaling.dat",
                         "# method grid springs seconds_per_step assembly factorization solve newton_per_step "
                         "cg_per_solve cpu_seconds_per_step  (blocks by method)");
  std::FILE* const f = file->get();
  std::vector<ScalingPoint> points;
  for (const std::string& method : scaling_methods) {
    std::fprintf(f, "# %s\n", method.c_str());
    for (const int size : plan.sizes) {
      throw_if_interrupted();
      SceneParams p = base;
      p.grid.M = p.grid.N = size;
      const Scene scene(p);
      ForceField field(scene);
      auto stepper = make_sweep_stepper(method, field);
      auto* const implicit = dynamic_cast<ImplicitEuler*>(stepper.get());
      const double h = implicit ? 0.01 : 1e-3;
      // Start from the state at t = 0.05 s, where the cloth is moving and stretched.
      Vector x = scene.initial_positions(), v = scene.initial_velocities();
      for (int k = 0; k < 5; ++k) stepper->step(h, x, v);
      const Vector x0 = x, v0 = v;
      const int steps = implicit ? 3 : 10;
      if (implicit) implicit->reset_timing();
      stepper->reset_counters();
      const double start = wall_seconds();
      const Timing t = time_runs(
          [&] {
            x = x0, v = v0;
            for (int k = 0; k < steps; ++k) stepper->step(h, x, v);
          },
          {.runs = plan.runs, .warmup = 1});
      // Per step: the timed runs', and the mean over every step taken, which the parts of an implicit step are.
      const StepCounters& n = stepper->counters();
      const double per_step = 1.0 / static_cast<double>(n.steps);
      ScalingPoint& point = points.emplace_back(ScalingPoint{.method = method,
                                                             .size = size,
                                                             .springs = scene.springs().size(),
                                                             .wall_per_step = t.median_wall / steps,
                                                             .cpu_per_step = t.fastest_cpu / steps});
      point.mean_wall_per_step = (wall_seconds() - start) * per_step;
      if (implicit) {
        point.assembly_per_step = implicit->timing().assembly * per_step;
        point.factorization_per_step = implicit->timing().factorization * per_step;
        point.solve_per_step = implicit->timing().solve * per_step;
      }
      point.newton_per_step = static_cast<double>(n.newton_iterations) * per_step;
      point.cg_per_solve =
          n.linear_solves > 0 ? static_cast<double>(n.cg_iterations) / static_cast<double>(n.linear_solves) : 0.0;
      record(sink, f, point, h);
      if (point.wall_per_step > plan.max_step_seconds) break;  // larger grids would take minutes
    }
    std::fprintf(f, "\n\n");
  }
  file->commit();
  return points;
}
// [scaling]

void write_scaling_fragment(const std::string& dir, const std::vector<ScalingPoint>& scaling,
                            const std::string& command) {
  std::vector<int> sizes;
  std::map<int, int> springs;
  for (const ScalingPoint& p : scaling) {
    if (std::find(sizes.begin(), sizes.end(), p.size) == sizes.end()) sizes.push_back(p.size);
    springs[p.size] = p.springs;
  }
  std::sort(sizes.begin(), sizes.end());
  // An exponent is fitted only over three sizes or more: two points always lie on a line.
  bool fit = false;
  for (const std::string& m : scaling_methods)
    fit = fit || std::count_if(scaling.begin(), scaling.end(), [&](const ScalingPoint& p) { return p.method == m; }) >= 3;
  std::vector<std::string> header = {"per step"};
  for (const int s : sizes)
    header.push_back(std::to_string(s) + " x " + std::to_string(s) + " (" + std::to_string(springs[s]) + " springs)");
  if (fit) header.push_back("exponent");
  MarkdownTable table(header, std::string("l").append(header.size() - 1, 'r'));
  const auto row = [&](const std::string& title, const std::string& method, auto cell, bool with_exponent) {
    std::vector<std::string> cells = {title};
    std::vector<double> x, y;
    for (const int s : sizes) {
      const auto it = std::find_if(scaling.begin(), scaling.end(),
                                   [&](const ScalingPoint& p) { return p.method == method && p.size == s; });
      cells.push_back(it == scaling.end() ? "(not run)" : cell(*it));
      if (it != scaling.end()) x.push_back(it->springs), y.push_back(it->cpu_per_step);
    }
    if (fit) cells.push_back(with_exponent && x.size() >= 3 ? format_fixed(log_slope(x, y), 2) : "");
    table.add_row(cells);
  };
  const auto time = [](const ScalingPoint& p) { return ms(p.cpu_per_step); };
  row("explicit Euler", "explicit_euler", time, true);
  row("RK4", "rk4", time, true);
  row("implicit Euler, direct", "implicit_euler", time, true);
  row("of which factorization", "implicit_euler",
      [](const ScalingPoint& p) { return std::to_string(std::lround(100 * p.factorization_per_step / p.mean_wall_per_step)) + " %"; },
      false);
  row("implicit Euler, CG", "implicit_euler/cg", time, true);
  row("Newton iterations per step", "implicit_euler/cg", [](const ScalingPoint& p) { return g(p.newton_per_step); }, false);
  row("CG iterations per solve", "implicit_euler/cg", [](const ScalingPoint& p) { return g(p.cg_per_solve); }, false);
  write_table_fragment(dir + "/scaling.md", table, command);
}

}  // namespace ch06
