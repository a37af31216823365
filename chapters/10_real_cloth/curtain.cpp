// Chapter 10's study of cloth that moves (see curtain.hpp): each scene's reference motion at every frame, each
// method of the chapter run on it and measured against it beside the size of the motion, the accuracy levels with
// the rule that a level the rest state meets is no win, implicit Euler's damping of a rigid rotation, and in the
// full run the same square metre at finer grids.
#include "curtain.hpp"

#include "study.hpp"

#include "analysis/lattice_frequency.hpp"
#include "analysis/reference_trajectory.hpp"
#include "analysis/trajectory_measures.hpp"
#include "model/single_spring.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace cloth;
using ch10::format;

namespace ch10 {

namespace {

constexpr double frame_rate = 60;  // the reference and the measures see the cloth every 1/60 s
constexpr double K = 1e5;          // the chapter's stiff fabric: one K for every family [N/m]

// [curtain_scenes]
/// A scene of the study: the chapter's fabric (ch10::fabric: 0.95 m square, 0.25 kg/m^2, D = 0.01, released from
/// rest) hung by `pins`, started turning at `swing` rad/s about the edge j = N-1, followed for T seconds.
struct CurtainScene {
  std::string tag;    ///< names its files
  std::string title;  ///< names it on the page
  PinSet pins;
  double swing;
  double T;
};

const std::vector<CurtainScene> scenes = {
    {"curtain", "the curtain, released flat", PinSet::edge, 0.0, 0.6},
    {"swing", "the curtain thrown down at 4 rad/s", PinSet::edge, -4.0, 0.8},
    {"corners", "the sheet hung by its four corners", PinSet::corners, 0.0, 0.5},
};
// [curtain_scenes]

SceneParams scene_params(const CurtainScene& c, int n) {
  SceneParams p = fabric(n, K);
  p.pins = c.pins;
  p.initial_swing = c.swing;
  return p;
}

/// The common flags that give the scene to a single-run program at n x n.
std::string scene_flags(const CurtainScene& c, int n) {
  const SceneParams p = scene_params(c, n);
  return format("--grid %dx%d --spacing %.4g --mass %.4g --K %g --damping %g --v0 0 --pins %s%s --t-end %g", n, n,
                p.grid.d, p.mass, K, p.damping, pin_set_name(p.pins),
                c.swing != 0 ? format(" --swing %g", c.swing).c_str() : "", c.T);
}

// [curtain_methods]
/// A method of the study and its steps [s]; no steps: 95 % of its stable step on the flat fabric (Chapter 7),
/// shortened to a whole number of steps per frame. Adding a method of the registry to the study is one line here.
struct MethodRow {
  std::string key;  ///< as ch10::make_method takes it
  std::vector<double> steps;
  std::size_t quick_steps = 3;  ///< how many of the steps the quick run tries (full Newton: seconds per run)
  bool finer_grids = true;      ///< whether the full run's finer grids try it (full Newton: minutes per run)
};
const std::vector<double> frame_steps = {1.0 / 30, 1.0 / 60, 1.0 / 120};
const std::vector<MethodRow> methods = {
    {"symplectic_euler", {}},
    {"rk4", {}},
    {"implicit_euler/one/cg", frame_steps},
    {"implicit_euler/cg", frame_steps, 1, false},
    {"local_global", frame_steps},
    {"xpbd/4sub", {1.0 / 60}},
    {"xpbd/16sub", {1.0 / 60}},
    {"xpbd/64sub", {1.0 / 60}},
    {"small_steps/64sub", {1.0 / 60}},
    {"small_steps/256sub", {1.0 / 60}},
    {"small_steps/512sub", {1.0 / 60}},
};
// [curtain_methods]

/// One run of a method and its measures against the reference.
struct CurtainRun {
  std::string method;
  double h = 0;
  long long steps = 0;
  double seconds = 0;  ///< thread CPU seconds of the stepping
  bool ok = true;
  std::string message;  ///< why it stopped, with the step and the time
  TrajectoryError error;
  double energy_lost = NAN;  ///< beyond the reference at T, as a fraction of the reference's peak kinetic energy
  double strain = 0;         ///< the largest spring strain over the frames
  double minimum = NAN;      ///< the first minimum of the free edge's mean height [s]
  std::vector<double> t, edge;
};

struct SceneResult {
  CurtainScene scene;
  int n = 20;
  ReferenceTrajectory reference;
  double check = -1;  ///< largest distance over the frames to the reference at the tighter tolerance, or -1
  double check_tolerance = 0;
  TrajectoryError motion;
  double peak_kinetic = 0, reference_strain = 0, reference_minimum = NAN;
  std::vector<double> t, edge;
  std::vector<CurtainRun> runs;
};

double explicit_step(const std::string& key, const SceneParams& p) {
  const double reach = key == "rk4" ? 2 * std::sqrt(2.0) : 2.0;  // on the imaginary axis (Chapter 7)
  return 0.95 * reach / lattice_fastest_frequency({K, K, K, p.mass});
}

// [curtain_run]
/// Runs `key` at step h (frame_interval / h or h / frame_interval whole) to T, keeping the state at every frame it
/// lands on; the stepping alone is timed. A failed step or a diverging state ends the run: a result, kept with
/// where it stopped.
CurtainRun run_method(const Scene& scene, const std::string& key, double h, double T, const SceneResult& ref) {
  ForceField field(scene);
  auto stepper = make_method(key, field);
  CurtainRun run;
  run.method = key;
  run.h = h;
  run.steps = std::llround(T / h);
  const long long every = std::max(1LL, std::llround(1 / (frame_rate * h)));  // steps between recorded frames
  std::vector<Vector> xs{scene.initial_positions()}, vs{scene.initial_velocities()};
  Vector x = xs[0], v = vs[0];
  const double start = thread_cpu_seconds();
  for (long long k = 1; k <= run.steps; ++k) {
    throw_if_interrupted();
    if (!stepper->step(h, x, v)) {
      run.ok = false;
      run.message = format("step %lld (t = %.4g s) failed: %s", k, static_cast<double>(k) * h,
                           stepper->failure().reason.c_str());
      break;
    }
    if (!x.allFinite() || x.cwiseAbs().maxCoeff() > 100) {
      run.ok = false;
      run.message = format("diverged at step %lld (t = %.4g s)", k, static_cast<double>(k) * h);
      break;
    }
    if (k % every == 0) xs.push_back(x), vs.push_back(v);
  }
  run.seconds = thread_cpu_seconds() - start;
  std::vector<Frame> frames;
  for (std::size_t f = 0; f < xs.size(); ++f) {
    frames.push_back({static_cast<double>(f) * static_cast<double>(every) * h, Vector(3 * scene.particle_count())});
    scene.all_positions(xs[f], frames.back().positions);
    run.t.push_back(frames.back().t);
  }
  run.edge = free_edge_height(scene.grid(), frames);
  run.strain = largest_strain(scene, frames);
  if (!run.ok) return run;
  run.error = trajectory_error(frames, ref.reference.frames);
  run.energy_lost = energy_lost(field.energy(x, v), ref.reference.energy.back(), ref.peak_kinetic).fraction;
  run.minimum = first_minimum_time(run.t, run.edge);
  return run;
}
// [curtain_run]

/// The scene's reference, its measures and every method's runs on the n x n grid; `quick`: the quick run's
/// settings (a looser reference, unchecked, and fewer full Newton runs).
SceneResult measure_scene(const CurtainScene& c, int n, bool quick) {
  SceneResult r;
  r.scene = c;
  r.n = n;
  const Scene scene(scene_params(c, n));
  ForceField field(scene);
  const int frames = static_cast<int>(std::lround(c.T * frame_rate));
  const double tolerance = quick ? 1e-8 : 1e-10;
  const double start = thread_cpu_seconds();
  r.reference = reference_trajectory(field, scene.initial_positions(), scene.initial_velocities(), c.T, frames,
                                     tolerance, &interrupt_flag());
  throw_if_interrupted();
  std::printf("%s %dx%d: reference dopri5 at %g, %lld steps, %.2f s\n", c.tag.c_str(), n, n, tolerance,
              r.reference.steps, thread_cpu_seconds() - start);
  if (!quick && n == 20) {
    r.check_tolerance = 1e-12;
    const ReferenceTrajectory tight = reference_trajectory(field, scene.initial_positions(), scene.initial_velocities(),
                                                           c.T, frames, r.check_tolerance, &interrupt_flag());
    throw_if_interrupted();
    r.check = trajectory_error(r.reference.frames, tight.frames).over_frames;
    std::printf("  against dopri5 at %g: %.2g m\n", r.check_tolerance, r.check);
  }
  r.motion = motion_size(r.reference.frames);
  for (const Energy& e : r.reference.energy) r.peak_kinetic = std::max(r.peak_kinetic, e.kinetic);
  r.reference_strain = largest_strain(scene, r.reference.frames);
  for (const Frame& f : r.reference.frames) r.t.push_back(f.t);
  r.edge = free_edge_height(scene.grid(), r.reference.frames);
  r.reference_minimum = first_minimum_time(r.t, r.edge);
  for (const MethodRow& m : methods) {
    if (n > 20 && !m.finer_grids) continue;
    std::vector<double> steps = m.steps;
    if (quick && steps.size() > m.quick_steps) steps.resize(m.quick_steps);
    if (steps.empty()) {  // a whole number of steps per frame, each below 95 % of the stable step
      const double per_frame = std::ceil(1 / (frame_rate * explicit_step(m.key, scene.params())));
      steps = {1 / (frame_rate * per_frame)};
    }
    for (double h : steps) {
      r.runs.push_back(run_method(scene, m.key, h, c.T, r));
      const CurtainRun& run = r.runs.back();
      std::printf("  %-18s h %-9.3g %7.3f s  error at T %.3g, over frames %.3g %s\n", m.key.c_str(), h, run.seconds,
                  run.error.at_end, run.error.over_frames, run.message.c_str());
    }
  }
  return r;
}

std::string metres(double x) {
  if (x >= 0.1) return format("%.3g m", x);
  if (x >= 1e-3) return format("%.3g cm", 100 * x);
  if (x >= 1e-6) return format("%.3g mm", 1e3 * x);
  return format("%.2g m", x);
}

/// The accuracy levels: "plausible" (5 % of the motion over the frames, the page defines it), 1 cm and 1 mm.
struct Level {
  std::string name;
  double metres;
};
std::vector<Level> levels(const SceneResult& r) {
  return {{"plausible (5 % of the motion)", 0.05 * r.motion.over_frames}, {"1 cm", 1e-2}, {"1 mm", 1e-3}};
}

// ---------------------------------------------------------------------------------------------------------------
// The tables.

MarkdownTable scenes_table(const std::vector<SceneResult>& results) {
  MarkdownTable t({"scene", "T [s]", "motion at T", "motion over the frames", "largest strain", "free edge lowest at",
                   "reference: dopri5 steps", "reference checked to"},
                  "lrrrrrrr");
  for (const SceneResult& r : results) {
    const std::string minimum = std::isnan(r.reference_minimum) ? "after T" : format("%.3f s", r.reference_minimum);
    t.add_row({r.scene.title, format("%g", r.scene.T), metres(r.motion.at_end), metres(r.motion.over_frames),
               format("%.2g", r.reference_strain), r.scene.tag == "corners" ? "-" : minimum,
               format("%lld", r.reference.steps), r.check < 0 ? "not checked (quick run)" : metres(r.check)});
  }
  return t;
}

std::string verdict_cell(const CurtainRun& run, double motion, double level) {
  if (!run.ok) return "-";
  switch (accuracy_verdict(run.error.over_frames, motion, level)) {
    case AccuracyVerdict::reached: return "yes";
    case AccuracyVerdict::missed: return "no";
    case AccuracyVerdict::met_by_rest: return "(met by standing still)";
  }
  return "?";
}

MarkdownTable runs_table(const SceneResult& r) {
  MarkdownTable t({"method", "h [s]", "CPU time [s]", "error at T", "error over the frames", "energy lost",
                   "largest strain", "phase: free edge lowest at", "1 cm", "1 mm"},
                  "lrrrrrrrll");
  for (const CurtainRun& run : r.runs) {
    if (!run.ok) {
      t.add_row({label(run.method), step_text(run.h), format("%.3g", run.seconds), run.message, "", "",
                 format("%.2g", run.strain), "", "-", "-"});
      continue;
    }
    std::string phase = "-";
    if (r.scene.tag != "corners")
      phase = std::isnan(run.minimum) ? "after T"
                                      : format("%.3f s (%+.3f)", run.minimum, run.minimum - r.reference_minimum);
    t.add_row({label(run.method), step_text(run.h), format("%.3g", run.seconds), metres(run.error.at_end),
               metres(run.error.over_frames), format("%.1f %%", std::abs(run.energy_lost) < 5e-4 ? 0.0 : 100 * run.energy_lost), format("%.2g", run.strain),
               phase, verdict_cell(run, r.motion.over_frames, 1e-2), verdict_cell(run, r.motion.over_frames, 1e-3)});
  }
  return t;
}

/// For each scene and level: the size of the motion beside it, and the fastest run that reached it over every
/// frame, or the note that standing still meets it.
MarkdownTable levels_table(const std::vector<SceneResult>& results) {
  MarkdownTable t({"scene", "motion over the frames", "accuracy over the frames", "fastest run that reached it",
                   "CPU time [s]", "fastest implicit or position-based run that reached it"},
                  "lrllrl");
  for (const SceneResult& r : results) {
    for (const Level& level : levels(r)) {
      const CurtainRun* best = nullptr;
      const CurtainRun* best_implicit = nullptr;
      for (const CurtainRun& run : r.runs) {
        if (!run.ok ||
            accuracy_verdict(run.error.over_frames, r.motion.over_frames, level.metres) != AccuracyVerdict::reached)
          continue;
        if (best == nullptr || run.seconds < best->seconds) best = &run;
        if (!is_explicit(run.method) && (best_implicit == nullptr || run.seconds < best_implicit->seconds))
          best_implicit = &run;
      }
      const std::string name =
          level.name[0] == 'p' ? format("%s: %s", level.name.c_str(), metres(level.metres).c_str()) : level.name;
      const auto describe = [](const CurtainRun* run) {
        return run == nullptr ? std::string("none") : label(run->method) + ", h = " + step_text(run->h);
      };
      if (accuracy_verdict(0, r.motion.over_frames, level.metres) == AccuracyVerdict::met_by_rest)
        t.add_row({r.scene.title, metres(r.motion.over_frames), name, "met by standing still: measures nothing", "",
                   ""});
      else
        t.add_row({r.scene.title, metres(r.motion.over_frames), name, describe(best),
                   best ? format("%.3g", best->seconds) : "", describe(best_implicit)});
    }
  }
  return t;
}

void write_runs_data(const std::string& out, const SceneResult& r) {
  std::string dat = format("# %s, %d x %d: method h steps cpu_seconds error_at_T error_over_frames energy_lost "
                           "largest_strain first_minimum status (motion at T %.6e, over the frames %.6e; reference "
                           "first minimum %.6e)\n",
                           r.scene.title.c_str(), r.n, r.n, r.motion.at_end, r.motion.over_frames, r.reference_minimum);
  for (const CurtainRun& run : r.runs)
    dat += format("%s %.6e %lld %.6e %.6e %.6e %.6e %.6e %.6e %s\n", run.method.c_str(), run.h, run.steps, run.seconds,
                  run.error.at_end, run.error.over_frames, run.energy_lost, run.strain, run.minimum,
                  run.ok ? "ok" : "failed");
  write_text(out, "curtain_" + r.scene.tag + ".dat", dat);
  // The free edge's mean height: the reference, then every run, one gnuplot index block each.
  std::string edge = "# t free_edge_mean_height; block 0 the reference, then one block per run in the order of curtain_" +
                     r.scene.tag + ".dat\n# reference\n";
  for (std::size_t k = 0; k < r.t.size(); ++k) edge += format("%.6f %.6e\n", r.t[k], r.edge[k]);
  for (const CurtainRun& run : r.runs) {
    edge += format("\n\n# %s h = %s\n", run.method.c_str(), step_text(run.h).c_str());
    for (std::size_t k = 0; k < run.t.size(); ++k) edge += format("%.6f %.6e\n", run.t[k], run.edge[k]);
  }
  write_text(out, "curtain_edge_" + r.scene.tag + ".dat", edge);
}

// ---------------------------------------------------------------------------------------------------------------
// Implicit Euler and a rigid rotation.

// [rotation]
/// Two particles hanging from a pinned edge by stiff springs (single_spring_params: no gravity, no damping), turned
/// rigidly about the edge at w0 rad/s: the exact motion turns forever at w0. Implicit Euler's angular rate after
/// each step, against the stiff-limit prediction the page derives: the k-th step turns the spring by the angle
/// a_1 = atan(h w0), a_{k+1} = atan(sin a_k / (2 - cos a_k)), and leaves it turning at w_k = sin(a_k) / h.
struct RotationRun {
  std::string method;
  double h;
  std::vector<double> t, w;  // the measured angular rate
};

RotationRun rotation(const std::string& method, double h, double Kspring, double w0, double T) {
  SceneParams p = single_spring_params(Kspring, 0);
  p.initial_velocity_z = 0;
  p.initial_swing = w0;
  const Scene scene(p);
  ForceField field(scene);
  auto stepper = make_method(method, field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  const double axis_y = (p.grid.N - 1) * p.grid.d;
  const auto rate = [&] {  // about the edge's line: (r x v)_x / |r|^2 of the first free particle
    const double dy = x[1] - axis_y, dz = x[2];
    return -(dy * v[2] - dz * v[1]) / (dy * dy + dz * dz);
  };
  RotationRun r{method, h, {0}, {rate()}};
  for (long long k = 1; k <= std::llround(T / h); ++k) {
    if (!stepper->step(h, x, v)) break;
    r.t.push_back(static_cast<double>(k) * h);
    r.w.push_back(rate());
  }
  return r;
}
// [rotation]

void rotation_study(const std::string& out, const std::string& command) {
  const double Kspring = 1e6, w0 = 10, T = 1;  // spring frequency 1000 rad/s: h sqrt(K/m) >= 8 at these steps
  MarkdownTable t({"h [s]", "h w0", "predicted w(T) / w0", "implicit Euler, Newton", "implicit Euler, 1 iteration",
                   "RK4 (at 1e-4 s)"},
                  "rrrrrr");
  std::string dat = "# t w_measured w_predicted; one block per (method, h): implicit_euler/exact then implicit_euler/one/exact "
                    "at h = 1/30, 1/60, 1/120, then rk4 at 1e-4\n";
  const RotationRun exact = rotation("rk4", 1e-4, Kspring, w0, T);
  // The stiff-limit recurrence of the page: the rate after each step of h.
  const auto predicted_rates = [&](double h) {
    std::vector<double> w = {w0};
    double a = std::atan(h * w0);
    for (long long k = 1; k <= std::llround(T / h); ++k, a = std::atan(std::sin(a) / (2 - std::cos(a))))
      w.push_back(std::sin(a) / h);
    return w;
  };
  for (double h : frame_steps) {
    const std::vector<double> prediction = predicted_rates(h);
    const double predicted = prediction.back();
    std::vector<std::string> row = {step_text(h), format("%.3g", h * w0), format("%.3f", predicted / w0)};
    for (const char* method : {"implicit_euler/exact", "implicit_euler/one/exact"}) {
      const RotationRun r = rotation(method, h, Kspring, w0, T);
      row.push_back(format("%.3f", r.w.back() / w0));
      dat += format("# %s h = %s\n", method, step_text(h).c_str());
      for (std::size_t k = 0; k < r.t.size(); ++k) dat += format("%.6f %.6e %.6e\n", r.t[k], r.w[k], prediction[k]);
      dat += "\n\n";
    }
    row.push_back(format("%.4f", exact.w.back() / w0));
    t.add_row(row);
  }
  dat += "# rk4 h = 1e-4\n";
  for (std::size_t k = 0; k < exact.t.size(); k += 100) dat += format("%.6f %.6e %.6e\n", exact.t[k], exact.w[k], w0);
  write_table_fragment(out + "/rotation.md", t, command);
  write_text(out, "rotation.dat", dat);
}

// ---------------------------------------------------------------------------------------------------------------
// The same square metre at finer grids (full run only).

void ladder(const std::string& out, const std::string& command) {
  MarkdownTable t({"scene", "grid", "motion over the frames", "reference steps", "method", "h [s]", "CPU time [s]",
                   "error over the frames"},
                  "llrrlrrr");
  std::string dat = "# scene n method h cpu_seconds error_over_frames motion_over_frames status\n";
  for (const CurtainScene& c : scenes) {
    if (c.tag == "corners") continue;
    for (int n : {20, 40, 80}) {
      // Beyond 20 x 20 with the quick run's settings (reference at 1e-8) and without full Newton: a finer grid's
      // runs cost up to (n / 20)^3 times as much.
      const SceneResult r = measure_scene(c, n, n > 20);
      for (const CurtainRun& run : r.runs) {
        t.add_row({c.title, format("%d x %d", n, n), metres(r.motion.over_frames), format("%lld", r.reference.steps),
                   label(run.method), step_text(run.h), format("%.3g", run.seconds),
                   run.ok ? metres(run.error.over_frames) : run.message});
        dat += format("%s %d %s %.6e %.6e %.6e %.6e %s\n", c.tag.c_str(), n, run.method.c_str(), run.h, run.seconds,
                      run.error.over_frames, r.motion.over_frames, run.ok ? "ok" : "failed");
      }
    }
  }
  write_table_fragment(out + "/curtain_ladder.md", t, command);
  write_text(out, "curtain_ladder.dat", dat);
}

// [sensitivity]
/// How fast two nearby curtains separate: references at 1e-10 and 1e-12 followed past the horizon, to 1 s.
void sensitivity(const std::string& out, const std::string& command) {
  const Scene scene(scene_params(scenes[0], 20));
  ForceField field(scene);
  const double T = 1;
  const int frames = 60;
  std::vector<ReferenceTrajectory> refs;
  for (double tolerance : {1e-10, 1e-12})
    refs.push_back(reference_trajectory(field, scene.initial_positions(), scene.initial_velocities(), T, frames,
                                        tolerance, &interrupt_flag()));
  throw_if_interrupted();
  std::vector<std::string> header = {"t [s]"}, row = {"largest distance [m]"};
  std::string dat = "# t largest_distance between the curtain's references at 1e-10 and 1e-12\n";
  for (int k = 0; k <= frames; ++k) {
    const double d = largest_distance(refs[0].frames[k].positions, refs[1].frames[k].positions);
    dat += format("%.6f %.6e\n", refs[0].frames[k].t, d);
    if (k > 0 && k % 6 == 0) {
      header.push_back(format("%.1f", refs[0].frames[k].t));
      row.push_back(format("%.1e", d));
    }
  }
  MarkdownTable t(header, std::string(header.size(), 'r'));
  t.add_row(row);
  write_table_fragment(out + "/curtain_sensitivity.md", t, command);
  write_text(out, "curtain_sensitivity.dat", dat);
}
// [sensitivity]

}  // namespace

std::vector<std::string> curtain_full_only() {
  return {"curtain_ladder.md", "curtain_ladder.dat", "curtain_sensitivity.md", "curtain_sensitivity.dat"};
}

std::vector<std::string> curtain_outputs(bool full) {
  std::vector<std::string> files = {"curtain_scenes.md", "curtain_levels.md", "curtain_motion.dat", "rotation.md",
                                    "rotation.dat"};
  for (const CurtainScene& c : scenes)
    for (const std::string& f : {"curtain_" + c.tag + ".md", "curtain_" + c.tag + ".dat", "curtain_edge_" + c.tag + ".dat",
                                 "curtain_flags_" + c.tag + ".md"})
      files.push_back(f);
  if (full)
    for (const std::string& f : curtain_full_only()) files.push_back(f);
  return files;
}

void curtain_study(bool quick, const std::string& out, const std::string& command) {
  std::vector<SceneResult> results;
  for (const CurtainScene& c : scenes) {
    results.push_back(measure_scene(c, 20, quick));
    write_table_fragment(out + "/curtain_" + c.tag + ".md", runs_table(results.back()), command);
    write_text_fragment(out + "/curtain_flags_" + c.tag + ".md", format("`%s`", scene_flags(c, 20).c_str()));
    write_runs_data(out, results.back());
  }
  write_table_fragment(out + "/curtain_scenes.md", scenes_table(results), command);
  std::string motion = "# scene T motion_at_T motion_over_frames reference_first_minimum\n";
  for (const SceneResult& r : results)
    motion += format("%s %g %.6e %.6e %.6e\n", r.scene.tag.c_str(), r.scene.T, r.motion.at_end, r.motion.over_frames,
                     r.reference_minimum);
  write_text(out, "curtain_motion.dat", motion);
  write_table_fragment(out + "/curtain_levels.md", levels_table(results), command);
  rotation_study(out, command);
  if (!quick) {
    sensitivity(out, command);
    ladder(out, command);
  }
}

}  // namespace ch10
