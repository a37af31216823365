// Chapter 12's drape (--drape-runs): Chapter 10's curtain of fabric, released flat from its top edge, with and
// without a bending term, by implicit Euler. What bending changes is measured by the sheet's RMS curvature (the
// hinge energy of unit rigidity, kappa_rms = sqrt(2 E / A)) over time and the hem's shape at the end; what it
// costs, by the time of a force and a Newton-matrix evaluation beside the springs'.
#include "report.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "model/bending.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
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
    {"hinge, B = 5e-6 N m (Chapter 10's fabric)", false, BendingModel::hinge, 5e-6},
    {"hinge, B = 6.1e-5 N m (a heavy fabric)", false, BendingModel::hinge, 6.1e-5},
    {"quadratic, B = 6.1e-5 N m", false, BendingModel::quadratic, 6.1e-5},
};

constexpr double drape_dt = 0.01, drape_t_end = 3.0;

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

// What a drape looks like at one moment: RMS curvature over the sheet [1/m], the hem's (row j = 0) spread out of
// the curtain's mean plane [m], and its folds (sign changes of its deviation from its mean, beyond 2 mm).
struct DrapeMeasure {
  double kappa_rms = 0, hem_spread = 0;
  int hem_folds = 0;
};

DrapeMeasure measure_drape(const Scene& scene, BendingEnergy& unit_hinges, const Vector& x) {
  DrapeMeasure m;
  const Grid& g = scene.grid();
  const double area = (g.M - 1) * (g.N - 1) * g.d * g.d;
  m.kappa_rms = std::sqrt(2 * unit_hinges.energy(x) / area);
  // The hanging curtain's plane is y = (N - 1) d (the pinned edge's); the hem's y is its deviation from it.
  std::vector<double> y;
  double mean = 0;
  for (int i = 0; i < g.M; ++i) {
    y.push_back(x[3 * scene.slot(g.particle(i, 0)) + 1]);
    mean += y.back() / g.M;
  }
  int sign = 0;
  for (const double yi : y) {
    m.hem_spread = std::max(m.hem_spread, std::abs(yi - mean));
    const int s = yi - mean > 2e-3 ? 1 : yi - mean < -2e-3 ? -1 : 0;
    if (s != 0 && sign != 0 && s != sign) ++m.hem_folds;
    if (s != 0) sign = s;
  }
  return m;
}

struct DrapeRun {
  std::vector<DrapeMeasure> history;  // every 0.1 s
  Vector x;                           // the end
  double seconds_per_step = 0;
  int steps = 0;
};

DrapeRun run_curtain(const DrapeCase& c) {
  const Scene scene(curtain(c));
  ForceField field(scene);
  BendingEnergy unit_hinges(scene, BendingModel::hinge, 1.0);  // the measure, the same for every case
  auto stepper = make_stepper("implicit_euler", field);
  DrapeRun run;
  run.x = scene.initial_positions();
  Vector v = scene.initial_velocities();
  const int steps = static_cast<int>(std::lround(drape_t_end / drape_dt)), every = 10;
  const auto start = std::chrono::steady_clock::now();
  for (; run.steps < steps; ++run.steps) {
    throw_if_interrupted();
    if (run.steps % every == 0) run.history.push_back(measure_drape(scene, unit_hinges, run.x));
    if (!stepper->step(drape_dt, run.x, v)) break;
  }
  run.seconds_per_step = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / run.steps;
  if (run.steps == steps) run.history.push_back(measure_drape(scene, unit_hinges, run.x));
  return run;
}

// drape_cost.md: one force evaluation and one Newton matrix of implicit Euler on the hanging curtain, springs
// alone and with each bending term (the terms' own cost is the difference).
void write_drape_cost(const std::string& dir, const std::string& command, const Vector& hanging) {
  MarkdownTable table({"curtain 20 x 20", "forces [ms]", "Newton matrix [ms]"}, "lrr");
  for (const DrapeCase& c : {drape_cases[0], drape_cases[3], drape_cases[4]}) {
    throw_if_interrupted();
    const Scene scene(curtain(c));
    ForceField field(scene);
    SparseMatrix A = field.pattern();
    const Vector v = Vector::Zero(scene.dof_count());
    Vector f(scene.dof_count());
    table.add_row({c.name, format_fixed(1e3 * median_seconds([&] { field.forces(hanging, v, f); }), 3),
                   format_fixed(1e3 * median_seconds([&] {
                     field.newton_matrix(hanging, v, drape_dt, StiffnessTreatment::symmetric, A);
                   }), 3)});
  }
  write_table_fragment(dir + "/drape_cost.md", table, command);
}

}  // namespace

std::vector<std::string> drape_outputs() { return {"drape_curvature.dat", "drape_hem.dat", "drape.md", "drape_cost.md"}; }

int drape_runs(const std::string& dir, const std::string& command) {
  std::vector<DrapeRun> runs;
  for (const DrapeCase& c : drape_cases) runs.push_back(run_curtain(c));
  // drape_curvature.dat: t, then kappa_rms of each case; drape_hem.dat: one index block per case, i d and the
  // hem's y deviation from the pinned edge's plane.
  OutputFile curvature(dir + "/drape_curvature.dat");
  std::fprintf(curvature.get(), "# t [s], then kappa_rms [1/m] of each case in drape.md's order\n");
  for (std::size_t k = 0; k < runs[0].history.size(); ++k) {
    std::fprintf(curvature.get(), "%.2f", 0.1 * static_cast<double>(k));
    for (const DrapeRun& r : runs)
      std::fprintf(curvature.get(), " %.6g", k < r.history.size() ? r.history[k].kappa_rms : NAN);
    std::fprintf(curvature.get(), "\n");
  }
  curvature.commit();
  OutputFile hem(dir + "/drape_hem.dat");
  const Scene any(curtain(drape_cases[0]));
  const Grid& g = any.grid();
  for (std::size_t c = 0; c < runs.size(); ++c) {
    std::fprintf(hem.get(), "# %s at t = %g s: x [m], y - (N-1) d [m], z [m]\n", drape_cases[c].name, drape_t_end);
    for (int i = 0; i < g.M; ++i) {
      const int s = any.slot(g.particle(i, 0));
      std::fprintf(hem.get(), "%.6g %.6g %.6g\n", runs[c].x[3 * s], runs[c].x[3 * s + 1] - (g.N - 1) * g.d,
                   runs[c].x[3 * s + 2]);
    }
    std::fprintf(hem.get(), "\n\n");
  }
  hem.commit();
  MarkdownTable table({"curtain", "kappa_rms at 1 s [1/m]", "kappa_rms at 3 s [1/m]", "hem spread at 3 s [cm]",
                       "hem folds at 3 s", "time per step [ms]"}, "lrrrrr");
  for (std::size_t c = 0; c < runs.size(); ++c) {
    const DrapeRun& r = runs[c];
    const bool done = r.history.size() == runs[0].history.size();
    const DrapeMeasure& end = r.history.back();
    table.add_row({drape_cases[c].name, format_number(r.history[std::min<std::size_t>(10, r.history.size() - 1)].kappa_rms, 3),
                   done ? format_number(end.kappa_rms, 3) : "failed at step " + std::to_string(r.steps),
                   format_fixed(100 * end.hem_spread, 2), std::to_string(end.hem_folds),
                   format_fixed(1e3 * r.seconds_per_step, 2)});
  }
  write_table_fragment(dir + "/drape.md", table, command);
  write_drape_cost(dir, command, runs[0].x);
  return 0;
}
