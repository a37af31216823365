// Chapter 10's study of cloth that moves, written out: the tables of the scenes, of each scene's runs and of the
// accuracy levels with the rule that a level the rest state meets is no win, and each scene's runs and free edge
// as data for curtain.gp (curtain_runs.hpp).
#include "curtain_runs.hpp"

#include <cmath>

using namespace cloth;

namespace ch10 {

std::string metres(double x) {
  if (x >= 0.1) return format("%.3g m", x);
  if (x >= 1e-3) return format("%.3g cm", 100 * x);
  if (x >= 1e-6) return format("%.3g mm", 1e3 * x);
  return format("%.2g m", x);
}

namespace {

/// The accuracy levels: "plausible" (5 % of the motion over the frames, the page defines it), 1 cm and 1 mm.
struct Level {
  std::string name;
  double metres;
};
std::vector<Level> levels(const SceneResult& r) {
  return {{"plausible (5 % of the motion)", 0.05 * r.motion.over_frames}, {"1 cm", 1e-2}, {"1 mm", 1e-3}};
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

}  // namespace

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
               metres(run.error.over_frames),
               format("%.1f %%", std::abs(run.energy_lost) < 5e-4 ? 0.0 : 100 * run.energy_lost),
               format("%.2g", run.strain), phase, verdict_cell(run, r.motion.over_frames, 1e-2), verdict_cell(run, r.motion.over_frames, 1e-3)});
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
  std::string edge = format("# t free_edge_mean_height; block 0 the reference, then one block per run in the order "
                            "of curtain_%s.dat\n# reference\n",
                            r.scene.tag.c_str());
  for (std::size_t k = 0; k < r.t.size(); ++k) edge += format("%.6f %.6e\n", r.t[k], r.edge[k]);
  for (const CurtainRun& run : r.runs) {
    edge += format("\n\n# %s h = %s\n", run.method.c_str(), step_text(run.h).c_str());
    for (std::size_t k = 0; k < run.t.size(); ++k) edge += format("%.6f %.6e\n", run.t[k], run.edge[k]);
  }
  write_text(out, "curtain_edge_" + r.scene.tag + ".dat", edge);
}

}  // namespace ch10
