// Chapter 12's drape (--drape-runs): Chapter 10's curtain of fabric, released flat from its top edge, with and
// without a bending term, by implicit Euler. What bending changes is measured by the sheet's RMS curvature (the
// hinge energy of unit rigidity, kappa_rms = sqrt(2 E / A)) over time, its sharpest fold, and the middle
// column's profile; what it costs, by the time of a force and a Newton-matrix evaluation beside the springs', and
// by the fill and time of the Newton matrix's factorization.
#include "report.hpp"

#include "base/format_number.hpp"
#include "integrators/block_ldu.hpp"
#include "integrators/method_registry.hpp"
#include "model/bending.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/output_kinds.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// One curtain: Chapter 10's fabric square (rho_A = 0.25 kg/m^2 at d = 5 cm, K = 1e5 N/m, D = 0.01), its top edge
// pinned, released from rest, with the springs of `families` and the bending term `model` of rigidity B.
struct DrapeCase {
  const char* name;
  bool flexion_springs;
  BendingModel model;
  double B;
};

constexpr DrapeCase drape_cases[] = {
    {"no bending (structural and shear springs)", false, BendingModel::flexion, 0},
    {"flexion springs of K = 1e5 N/m (Chapter 10)", true, BendingModel::flexion, 0},
    {"quadratic, B = 5e-6 N m (Chapter 10's fabric)", false, BendingModel::quadratic, 5e-6},
    {"hinge, B = 6.1e-5 N m (a heavy fabric)", false, BendingModel::hinge, 6.1e-5},
    {"quadratic, B = 3.9e-2 N m (the flexion springs at 1/m)", false, BendingModel::quadratic, 3.9e-2},
};

constexpr double drape_dt = 0.01, drape_t_end = 2.0, drape_t_early = 0.5;
constexpr int sample_every = 2;  // steps between two measurements of the history

SceneParams curtain(const DrapeCase& c) {
  SceneParams p;
  p.grid = Grid{20, 20, 0.05};
  p.mass = 6.25e-4;
  p.stiffness = 1e5;
  p.damping = 0.01;
  p.initial_velocity_z = 0;
  p.pins = PinSet::edge;
  p.families.on[static_cast<int>(SpringFamily::flexion)] = c.flexion_springs;
  if (c.model != BendingModel::flexion) {
    p.bending = c.model;
    p.bending_rigidity = c.B;
  }
  return p;
}

// What a drape looks like at one moment: the RMS curvature over the sheet [1/m] and the sharpest fold, the
// largest hinge angle [rad].
struct DrapeMeasure {
  double kappa_rms = 0, sharpest = 0;
};

DrapeMeasure measure_drape(const Scene& scene, BendingEnergy& unit_hinges, const Vector& x, Vector& all) {
  DrapeMeasure m;
  const Grid& g = scene.grid();
  const double area = (g.M - 1) * (g.N - 1) * g.d * g.d;
  m.kappa_rms = std::sqrt(2 * unit_hinges.energy(x) / area);
  scene.all_positions(x, all);
  for (const Hinge& h : unit_hinges.hinges()) {
    Vector12 y;
    for (int k = 0; k < 4; ++k) y.segment<3>(3 * k) = all.segment<3>(3 * h.particle[static_cast<std::size_t>(k)]);
    m.sharpest = std::max(m.sharpest, std::abs(hinge_angle(y)));
  }
  return m;
}

struct DrapeRun {
  std::vector<DrapeMeasure> history;  // every sample_every steps
  Vector early, x;                    // the free positions at drape_t_early and at the end
  double seconds_per_step = 0, newton_per_step = 0, factorizations_per_step = 0;
  int steps = 0;
};

// By implicit Euler with the definite Newton matrix (Choi and Ko's springs, the hinges' Gauss-Newton part): the
// exact one turns indefinite where springs are compressed, and on the quadratic B = 5e-6 run LDL^T meets a
// singular pivot at step 67, where Newton's method takes the definite matrix anyway (definite_fallbacks).
DrapeRun run_curtain(const DrapeCase& c) {
  const Scene scene(curtain(c));
  ForceField field(scene);
  BendingEnergy unit_hinges(scene, BendingModel::hinge, 1.0);  // the measure, the same for every case
  MethodSettings settings;
  settings.newton.treatment = StiffnessTreatment::definite;
  auto stepper = make_stepper("implicit_euler", field, settings);
  DrapeRun run;
  run.x = scene.initial_positions();
  Vector v = scene.initial_velocities(), all(3 * scene.particle_count());
  const int steps = static_cast<int>(std::lround(drape_t_end / drape_dt));
  const int early = static_cast<int>(std::lround(drape_t_early / drape_dt));
  const double start = thread_cpu_seconds();
  for (; run.steps < steps; ++run.steps) {
    throw_if_interrupted();
    if (run.steps % sample_every == 0) run.history.push_back(measure_drape(scene, unit_hinges, run.x, all));
    if (run.steps == early) run.early = run.x;
    if (!stepper->step(drape_dt, run.x, v)) break;
  }
  run.seconds_per_step = (thread_cpu_seconds() - start) / run.steps;
  run.newton_per_step = static_cast<double>(stepper->counters().newton_iterations) / run.steps;
  run.factorizations_per_step = static_cast<double>(stepper->counters().factorizations) / run.steps;
  if (run.steps == steps) run.history.push_back(measure_drape(scene, unit_hinges, run.x, all));
  return run;
}

// drape_cost.md: one force evaluation, one Newton matrix of implicit Euler and one factorization of it (the
// block LDL^T that implicit Euler uses with the definite matrix) on the hanging curtain, springs alone and with
// each bending term: the terms' own cost is the difference, and the factor's blocks say where the fill comes from.
void write_drape_cost(const std::string& dir, const std::string& command, const Vector& hanging) {
  MarkdownTable table({"curtain 20 x 20", "forces [ms]: median (fastest-slowest)",
                       "Newton matrix [ms]: median (fastest-slowest)", "3x3 blocks: matrix (all), L (below the diagonal)",
                       "one factorization [ms]: median (fastest-slowest)"}, "lrrrr");
  for (const DrapeCase& c : {drape_cases[0], drape_cases[2], drape_cases[3]}) {
    throw_if_interrupted();
    const Scene scene(curtain(c));
    ForceField field(scene);
    SparseMatrix A = field.pattern();
    const Vector v = Vector::Zero(scene.dof_count());
    Vector f(scene.dof_count());
    const std::string newton = milliseconds_cell(
        [&] { field.newton_matrix(hanging, v, drape_dt, StiffnessTreatment::definite, A); });
    BlockLDU factor;
    factor.analyze(A, BlockLDU::Symmetry::symmetric);
    std::string blocks = std::to_string(A.nonZeros() / 9);
    blocks += ", ";
    blocks += std::to_string(factor.factor_blocks());
    table.add_row({c.name, milliseconds_cell([&] { field.forces(hanging, v, f); }), newton, blocks,
                   milliseconds_cell([&] { factor.factorize(A); })});
  }
  write_table_fragment(dir + "/drape_cost.md", table, command);
}

}  // namespace

OutputList drape_outputs() {
  using namespace cloth::output_kinds;
  return {{"drape_curvature.dat", figure, "the curtain's RMS curvature over time, per bending case"},
          {"drape_profile.dat", figure, "the middle column's profile at 0.5 s and 2 s, per bending case"},
          {"drape.md", fragment, "what each bending case changes in the hanging curtain"},
          {"drape_cost.md", fragment, "a force and a Newton-matrix evaluation with each bending term"}};
}

namespace {

// drape_curvature.dat: t, then kappa_rms of each case; drape_profile.dat: per case, the middle column
// i = M/2 seen from the side (y, z) at drape_t_early, then at the end, as two gnuplot index blocks.
void write_drape_data(const std::string& dir, const std::vector<DrapeRun>& runs) {
  OutputFile curvature(dir + "/drape_curvature.dat");
  std::fprintf(curvature.get(), "# t [s], then kappa_rms [1/m] of each case in drape.md's order\n");
  for (std::size_t k = 0; k < runs[0].history.size(); ++k) {
    std::fprintf(curvature.get(), "%.2f", sample_every * drape_dt * static_cast<double>(k));
    for (const DrapeRun& r : runs)
      std::fprintf(curvature.get(), " %.6g", k < r.history.size() ? r.history[k].kappa_rms : NAN);
    std::fprintf(curvature.get(), "\n");
  }
  curvature.commit();
  OutputFile profile(dir + "/drape_profile.dat");
  const Scene scene(curtain(drape_cases[0]));
  const Grid& g = scene.grid();
  Vector all(3 * scene.particle_count());
  for (std::size_t c = 0; c < runs.size(); ++c)
    for (const Vector* x : {&runs[c].early, &runs[c].x}) {
      std::fprintf(profile.get(), "# %s at t = %g s: y [m], z [m] of the column i = %d, j = N-1 (pinned) to 0\n",
                   drape_cases[c].name, x == &runs[c].x ? drape_t_end : drape_t_early, g.M / 2);
      if (x->size() == scene.dof_count()) {
        scene.all_positions(*x, all);
        for (int j = g.N - 1; j >= 0; --j) {
          const int p = g.particle(g.M / 2, j);
          std::fprintf(profile.get(), "%.6g %.6g\n", all[3 * p + 1], all[3 * p + 2]);
        }
      }
      std::fprintf(profile.get(), "\n\n");
    }
  profile.commit();
}

}  // namespace

int drape_runs(const std::string& dir, const std::string& command) {
  std::vector<DrapeRun> runs;
  for (const DrapeCase& c : drape_cases) runs.push_back(run_curtain(c));  // 1. the curtains
  write_drape_data(dir, runs);                                             // 2. the figure's data
  MarkdownTable table({"curtain", "kappa_rms at 0.5 s [1/m]", "kappa_rms at 2 s [1/m]", "sharpest fold at 2 s [deg]",
                       "Newton iterations per step", "factorizations per step", "time per step [ms]"}, "lrrrrrr");
  const auto at = [](const DrapeRun& r, std::size_t k) { return r.history[std::min(k, r.history.size() - 1)]; };
  const auto early = static_cast<std::size_t>(std::lround(drape_t_early / drape_dt / sample_every));
  for (std::size_t c = 0; c < runs.size(); ++c) {                          // 3. what each looks like
    const DrapeRun& r = runs[c];
    const bool done = r.history.size() == runs[0].history.size();
    table.add_row({drape_cases[c].name, format_significant(at(r, early).kappa_rms, 3),
                   done ? format_significant(r.history.back().kappa_rms, 3) : "failed at step " + std::to_string(r.steps),
                   done ? format_fixed(r.history.back().sharpest * 180 / std::numbers::pi, 1) : "",
                   format_fixed(r.newton_per_step, 2), format_fixed(r.factorizations_per_step, 2),
                   format_fixed(1e3 * r.seconds_per_step, 2)});
  }
  write_table_fragment(dir + "/drape.md", table, command);
  write_drape_cost(dir, command, runs[0].x);                               // 4. and what it costs
  return 0;
}
