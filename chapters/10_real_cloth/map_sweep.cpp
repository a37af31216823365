// Measuring a part of Chapter 10's map (see map_sweep.hpp): the reference motion, then every program as a ladder
// of ever finer settings, each rung measured against the reference over every frame.
#include "map_sweep.hpp"

#include "map_runs.hpp"
#include "study.hpp"

#include "analysis/lattice_frequency.hpp"
#include "analysis/reference_trajectory.hpp"
#include "analysis/trajectory_measures.hpp"
#include "base/input_error.hpp"
#include "program/build_info.hpp"
#include "program/interrupt.hpp"
#include "program/timing.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

using namespace cloth;

namespace ch10 {

std::string MapPart::name() const { return format("%s_%d_1e%d", scene.c_str(), n, static_cast<int>(std::lround(std::log10(K)))); }

MapPart parse_map_part(const std::string& name) {
  const std::string accepted = "expected <scene>_<n>_1e<e>: scene curtain or swing, n from 4 to 400, e from 2 to 7 "
                               "(for example curtain_40_1e4)";
  char scene[16] = {};
  int n = 0, e = 0;
  char end = 0;
  if (std::sscanf(name.c_str(), "%15[a-z]_%d_1e%d%c", scene, &n, &e, &end) != 3 ||
      (std::string(scene) != "curtain" && std::string(scene) != "swing") || n < 4 || n > 400 || e < 2 || e > 7)
    throw InputError("--part " + name + ": " + accepted);
  return {scene, n, std::pow(10.0, e)};
}

std::vector<MapPart> full_map() {
  std::vector<MapPart> parts;
  for (int n : {20, 40, 80, 160})
    for (double K : {1e3, 1e4, 1e5, 1e6})
      for (const char* scene : {"curtain", "swing"}) parts.push_back({scene, n, K});
  return parts;
}

namespace {

// [map_ladders]
/// A program of the map as a ladder of settings, rung 0 the coarsest: run(k) measures rung k.
struct Series {
  std::string side;     ///< "book" or "peer"
  std::string program;  ///< the book's configuration name, or the peer's name
  std::string forces;   ///< "book" or "plain"
  std::function<std::string(int)> setting;
  std::function<MapRun(int)> run;
};

std::vector<Series> series_of(const Scene& scene, double T) {
  const SceneParams& p = scene.params();
  const double omega = lattice_fastest_frequency({p.stiffness, p.stiffness, p.stiffness, p.mass});
  const double frame = 1.0 / 60;
  // An explicit method's rung 0: the largest step below 95 % of its stable step with a whole number per frame.
  const auto stable = [omega, frame](double reach, int k) { return frame / (std::ceil(frame * omega / (0.95 * reach)) * std::pow(2, k)); };
  const auto step = [](double h) { return "h = " + step_text(h); };
  const auto frames_step = [](int k) { return (1.0 / 30) / std::pow(2, k); };  // 1/30, 1/60, 1/120, ...
  const double se = 2, rk4 = 2 * std::sqrt(2.0);
  std::vector<Series> s;
  s.push_back({"book", "symplectic_euler", "book", [=](int k) { return step(stable(se, k)); },
               [=, &scene](int k) { return book_run(scene, "symplectic_euler", stable(se, k), T); }});
  s.push_back({"book", "rk4", "book", [=](int k) { return step(stable(rk4, k)); },
               [=, &scene](int k) { return book_run(scene, "rk4", stable(rk4, k), T); }});
  const auto tolerance = [](int k) { return std::pow(10.0, -2 - k); };  // 1e-2, 1e-3, ...
  s.push_back({"book", "dopri5", "book", [=](int k) { return format("tol = %g", tolerance(k)); },
               [=, &scene](int k) { return book_dopri5_run(scene, tolerance(k), T); }});
  for (const char* name : {"implicit_euler/one/cg", "implicit_euler", "local_global"})
    s.push_back({"book", name, "book", [=](int k) { return step(frames_step(k)); },
                 [=, &scene](int k) { return book_run(scene, name, frames_step(k), T); }});
  const auto xpbd = [](int k) { return format("xpbd/%dsub", 4 << (2 * k)); };  // 4, 16, 64, ... substeps
  s.push_back({"book", "xpbd", "book", [=](int k) { return xpbd(k) + ", h = 1/60"; },
               [=, &scene](int k) { return book_run(scene, xpbd(k), frame, T); }});
  const auto small = [](int k) { return format("small_steps/%dsub", 32 << k); };  // 32, 64, 128, ... substeps
  s.push_back({"book", "small_steps", "book", [=](int k) { return small(k) + ", h = 1/60"; },
               [=, &scene](int k) { return book_run(scene, small(k), frame, T); }});
  for (Forces f : {Forces::plain, Forces::book}) {
    const std::string forces = f == Forces::plain ? "plain" : "book";
    s.push_back({"peer", "odeint_rk4", forces, [=](int k) { return step(stable(rk4, k)); },
                 [=, &scene](int k) { return odeint_rk4_run(scene, f, stable(rk4, k), T); }});
    s.push_back({"peer", "odeint_dopri5", forces, [=](int k) { return format("tol = %g", tolerance(k)); },
                 [=, &scene](int k) { return odeint_dopri5_run(scene, f, tolerance(k), T); }});
    const auto loose = [](int k) { return std::pow(10.0, -1 - k); };  // 1e-1, 1e-2, ...
    s.push_back({"peer", "cvode_bdf", forces, [=](int k) { return format("tol = %g", loose(k)); },
                 [=, &scene](int k) { return cvode_run(scene, f, loose(k), 5, T); }});
    s.push_back({"peer", "cvode_bdf/max_order_2", forces, [=](int k) { return format("tol = %g", loose(k)); },
                 [=, &scene](int k) { return cvode_run(scene, f, loose(k), 2, T); }});
    s.push_back({"peer", "arkode_backward_euler", forces, [=](int k) { return step(frames_step(k)); },
                 [=, &scene](int k) { return arkode_run(scene, f, frames_step(k), T); }});
  }
  s.push_back({"peer", "plain_xpbd", "plain", [=](int k) { return format("%d substeps of 1 sweep per 1/60 s", 32 << k); },
               [=, &scene](int k) { return plain_xpbd_run(scene, 32 << k, T); }});
  return s;
}
// [map_ladders]

// [map_horizon]
/// The reference over the longest horizon it is verified on: Dormand-Prince at the plan's tolerance and again at a
/// tenth of it, both to `longest`, cut at the last multiple of 0.1 s up to which the two agree within
/// `reference_agreement` at every frame. The curtain amplifies a small difference by 10^7 in 0.6 s on 20 x 20
/// (the sensitivity study), and more on finer grids, so a fixed horizon would measure the reference's own error
/// there; this one follows the grid and the stiffness.
ReferenceTrajectory verified_reference(ForceField& field, const Scene& scene, double longest, const SweepPlan& plan) {
  const int frames = static_cast<int>(std::lround(60 * longest));
  const auto reference = [&](double tolerance) {
    ReferenceTrajectory r = reference_trajectory(field, scene.initial_positions(), scene.initial_velocities(), longest,
                                                 frames, tolerance, &interrupt_flag());
    throw_if_interrupted();
    return r;
  };
  ReferenceTrajectory ref = reference(plan.reference_tolerance);
  const ReferenceTrajectory check = reference(plan.reference_tolerance / 10);
  int verified = 0;
  while (verified < frames && largest_distance(ref.frames[verified + 1].positions,
                                               check.frames[verified + 1].positions) <= plan.reference_agreement)
    ++verified;
  verified -= verified % 6;  // whole multiples of 0.1 s, so that every ladder's coarsest step (1/30 s) divides it
  if (verified < 6) throw std::runtime_error("the references disagree before t = 0.1 s: no horizon to measure on");
  ref.frames.resize(static_cast<std::size_t>(verified) + 1);
  ref.energy.resize(std::min(ref.energy.size(), ref.frames.size()));
  return ref;
}
// [map_horizon]

}  // namespace

double measure_part(const MapPart& part, const SweepPlan& plan, const std::string& dir, const std::string& command) {
  SceneParams p = fabric(part.n, part.K);
  p.pins = PinSet::edge;
  p.initial_swing = part.scene == "swing" ? -4.0 : 0.0;
  const Scene scene(p);
  ForceField field(scene);
  const double start = thread_cpu_seconds();
  ReferenceTrajectory ref = verified_reference(field, scene, part.scene == "swing" ? 0.8 : 0.6, plan);
  const double reference_seconds = thread_cpu_seconds() - start;
  const double T = ref.frames.back().t;
  const TrajectoryError motion = motion_size(ref.frames);
  std::string dat = format("# part %s scene %s n %d K %g T %g motion_over_frames %.6e motion_at_T %.6e "
                           "reference_tolerance %g reference_agreement %g reference_steps %lld reference_seconds %.3f\n"
                           "# measured by %s\n# built %s\n"
                           "# side program forces setting steps seconds error_at_T error_over_frames status\n",
                           part.name().c_str(), part.scene.c_str(), part.n, part.K, T, motion.over_frames,
                           motion.at_end, plan.reference_tolerance, plan.reference_agreement, ref.steps, reference_seconds, command.c_str(),
                           build_description().c_str());
  std::printf("%s: horizon %.2f s, motion %.3g m, references %.1f s\n", part.name().c_str(), T, motion.over_frames,
              reference_seconds);
  // [map_measure]
  double best_to_finest = INFINITY;  // the fastest run so far that reached 1 mm: no slower run can win a cell
  for (const Series& series : series_of(scene, T)) {
    double last_seconds = 0, last_error = INFINITY;
    int stalled = 0, failed = 0;
    for (int k = 0; k < plan.max_runs_per_series; ++k) {
      // The ladder's cost model: a rung costs about twice the one before (twice the steps, or a tenth of the
      // tolerance for the adaptive peers). A rung predicted over the budget is not started; nor one predicted
      // prune_factor times slower than a run that reached 1 mm once the ladder is plausible (5 % of the motion),
      // ten times that before, so that the implicit and position-based column is measured where it can be.
      const bool plausible = last_error <= 0.05 * motion.over_frames;
      const double prune = (plausible ? 1 : 10) * plan.prune_factor * best_to_finest;
      if (k > 0 && (2 * last_seconds > plan.run_budget || 2 * last_seconds > prune)) break;
      set_sundials_run_cap(std::min(plan.run_budget, std::max(10.0, plan.sundials_cap_factor * best_to_finest)));
      const MapRun run = series.run(k);
      TrajectoryError error{NAN, NAN, 0};
      if (run.ok) error = trajectory_error(run.frames, ref.frames);
      dat += format("%s %s %s \"%s\" %lld %.6e %.6e %.6e %s\n", series.side.c_str(), series.program.c_str(),
                    series.forces.c_str(), series.setting(k).c_str(), run.steps, run.seconds, error.at_end,
                    error.over_frames, run.ok ? "ok" : "failed");
      std::printf("  %-4s %-24s %-5s %-40s %8.3f s  error %.3g %s\n", series.side.c_str(), series.program.c_str(),
                  series.forces.c_str(), series.setting(k).c_str(), run.seconds, error.over_frames, run.note.c_str());
      std::fflush(stdout);
      // The rows so far, kept beside the part's file: a sweep stopped in the middle of an hours-long part keeps
      // what it measured (the tables read only finished parts).
      write_text(dir, "map_" + part.name() + ".dat.partial", dat);
      last_seconds = run.seconds;
      if (!run.ok) {
        if (++failed == 3) break;  // three rungs in a row that did not finish: the ladder has no finer luck coming
        continue;
      }
      failed = 0;
      if (error.over_frames <= 1e-3) {
        best_to_finest = std::min(best_to_finest, run.seconds);
        break;
      }
      stalled = error.over_frames > 0.8 * last_error ? stalled + 1 : 0;  // a ladder converging to another motion
      if (stalled == 2) break;
      last_error = error.over_frames;
    }
  }
  // [map_measure]
  write_text(dir, "map_" + part.name() + ".dat", dat);
  std::remove((dir + "/map_" + part.name() + ".dat.partial").c_str());
  return reference_seconds;
}

}  // namespace ch10
