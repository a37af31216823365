// Chapter 4's study of the implicit step as a minimisation (the section on the incremental potential): why the
// residual line search fails from the flat curtain, and what the minimising form does at frame-rate steps.
#include "potential_study.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "model/report_cases.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

namespace ch04 {

using namespace cloth;

namespace {

// The curtain: the report's fabric hung by one edge and released flat and at rest (20 x 20, 5 cm apart,
// m = 6.25e-4 kg, K = 1e5 N/m, D = 0.01 N s/m), where a frame step first asks Newton for a large motion.
SceneParams flat_curtain(SceneParams p) {
  p.grid.M = p.grid.N = 20;
  p.grid.d = 0.05;
  p.mass = 6.25e-4;
  p.stiffness = 1e5;
  p.flexion_stiffness.reset();
  p.damping = 0.01;
  p.damping_model = DampingModel::projected;
  p.initial_velocity_z = 0;
  p.pins = PinSet::edge;
  return p;
}

}  // namespace

// The first frame step (h = 1/60 s) of the flat curtain with each line search, iteration by iteration:
// |r|_inf, the step fraction the search took, and (minimising) Phi. Full Newton, exact matrix, the
// residual search allowed `residual_iterations`.
void flat_step_history(const SceneParams& base, const std::string& dir, const std::string& command) {
  const Scene scene(flat_curtain(base));
  const double h = 1.0 / 60;
  struct History {
    std::vector<double> r, phi, a;
    bool ok;
  };
  const auto history = [&](LineSearch search) {
    ForceField field(scene);
    NewtonSettings s;
    s.line_search = search;
    s.max_iterations = 20;
    const auto made = make_newton_stepper("implicit_euler", field, {s});
    Vector x = scene.initial_positions(), v = scene.initial_velocities();
    const bool ok = made->step(h, x, v);
    const StageNewton& n = made->newton();
    return History{n.residual_history(), n.potential_history(), n.step_fractions(), ok};
  };
  const History residual = history(LineSearch::residual), potential = history(LineSearch::potential);
  MarkdownTable table({"iteration k", "residual search: r_k (max norm) [N s]", "step fraction", "Phi search: r_k [N s]",
                       "Phi_k [J]", "step fraction"},
                      "rrrrrr");
  const std::size_t rows = std::max(residual.r.size(), potential.r.size());
  const auto cell = [](const std::vector<double>& v, std::size_t k, int digits) {
    return k < v.size() ? format_number(v[k], digits) : std::string();
  };
  for (std::size_t k = 0; k < rows; ++k)
    table.add_row({std::to_string(k), cell(residual.r, k, 3), k > 0 ? cell(residual.a, k - 1, 3) : "",
                   cell(potential.r, k, 3), cell(potential.phi, k, 6), k > 0 ? cell(potential.a, k - 1, 3) : ""});
  table.add_row({"outcome", residual.ok ? "converged" : "not converged in 20", "",
                 potential.ok ? "converged" : "not converged in 20", "", ""});
  write_table_fragment(dir + "/flat_step.md", table, command);
}

namespace {

// How the frozen dampers' difference shrinks with h, on the report scene's damped case (K = 200, D = 20) where
// damping is strong enough to see it: to T = 0.3 s at h = 0.01, 0.005, 0.0025; rows added to `frozen`.
void frozen_dampers_with_h(const SceneParams& base, const RunSettings& base_run, MarkdownTable& frozen) {
  const Scene damped(with_K_and_D(base, 200, 20));
  double previous = 0;
  for (const double h : {0.01, 0.005, 0.0025}) {
    RunSettings run = base_run;
    run.dt = h;
    run.t_end = 0.3;
    RunResult r[2];
    for (int k = 0; k < 2; ++k) {
      ForceField field(damped);
      NewtonSettings s;
      s.line_search = k ? LineSearch::residual : LineSearch::potential;
      const auto made = make_newton_stepper("implicit_euler", field, {s});
      r[k] = simulate(*made, run, false);
      throw_if_interrupted();
      if (r[k].status != RunStatus::ok) throw std::runtime_error("implicit_euler " + r[k].message);
    }
    ForceField field(damped);
    const double d = (r[0].x - r[1].x).lpNorm<Eigen::Infinity>();
    frozen.add_row({"report scene K = 200, D = 20, T = 0.3 s, h = " + format_number(h) +
                        (previous > 0 ? " (ratio " + format_number(previous / d, 3) + ")" : ""),
                    format_number(d, 3), format_number(field.energy(r[0].x, r[0].v).total(), 6),
                    format_number(field.energy(r[1].x, r[1].v).total(), 6)});
    previous = d;
  }
}

}  // namespace

// Implicit Euler on the curtain at three frame-rate steps: full Newton minimising Phi, full Newton with the
// residual search, and one iteration; each run's outcome, Newton iterations per step and seconds. Returns the
// largest position difference at T between the two full-Newton forms where both finish (the frozen dampers'
// effect at frame rate), by step.
void curtain_runs(const SceneParams& base, const RunSettings& base_run, const std::string& dir,
                  const std::string& command) {
  const Scene scene(flat_curtain(base));
  MarkdownTable table({"h [s]", "Newton", "line search", "matrix", "outcome", "Newton iterations per step",
                       "seconds"},
                      "llllrrr");
  MarkdownTable frozen({"h [s]", "largest position difference at T, frozen against current dampers [m]",
                        "E(T), frozen [J]", "E(T), current [J]"},
                       "lrrr");
  for (const int per_second : {30, 60, 120}) {
    RunSettings run = base_run;
    run.dt = 1.0 / per_second;
    run.t_end = 0.5;
    std::optional<RunResult> full[2];
    struct Setting {
      NewtonVariant variant;
      LineSearch search;
      StiffnessTreatment treatment;
    };
    for (const auto& [variant, search, treatment] :
         {Setting{NewtonVariant::full, LineSearch::potential, StiffnessTreatment::exact},
          Setting{NewtonVariant::full, LineSearch::potential, StiffnessTreatment::definite},
          Setting{NewtonVariant::full, LineSearch::residual, StiffnessTreatment::exact},
          Setting{NewtonVariant::one, LineSearch::potential, StiffnessTreatment::exact}}) {
      ForceField field(scene);
      NewtonSettings s;
      s.variant = variant;
      s.line_search = search;
      s.treatment = treatment;
      const auto made = make_newton_stepper("implicit_euler", field, {s});
      RunResult r = simulate(*made, run, false);
      throw_if_interrupted();
      const bool ok = r.status == RunStatus::ok;
      table.add_row({"1/" + std::to_string(per_second), newton_variant_name(variant),
                     variant == NewtonVariant::one ? "none" : line_searches().name(search),
                     std::string(stiffness_treatments().name(treatment)) +
                         (search == LineSearch::potential && treatment == StiffnessTreatment::exact &&
                                  variant == NewtonVariant::full
                              ? " (" + std::to_string(r.counters.definite_fallbacks) + " definite)"
                              : ""),
                     ok ? "finishes" : "**fails at step " + std::to_string(r.failed_step) + "**",
                     format_fixed(r.newton_iterations_per_step(), 2), format_number(r.wall_seconds, 2)});
      if (variant == NewtonVariant::full && treatment == StiffnessTreatment::exact && ok)
        full[search == LineSearch::residual ? 1 : 0] = std::move(r);
    }
    if (full[0] && full[1]) {
      ForceField field(scene);
      frozen.add_row({"1/" + std::to_string(per_second), format_number((full[0]->x - full[1]->x).lpNorm<Eigen::Infinity>(), 3),
                      format_number(field.energy(full[0]->x, full[0]->v).total(), 6),
                      format_number(field.energy(full[1]->x, full[1]->v).total(), 6)});
    }
  }
  write_table_fragment(dir + "/curtain_runs.md", table, command);
  frozen_dampers_with_h(base, base_run, frozen);
  write_table_fragment(dir + "/frozen_dampers.md", frozen, command);
}

}  // namespace ch04
