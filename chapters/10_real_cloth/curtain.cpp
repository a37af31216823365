// Chapter 10's study of cloth that moves (see curtain.hpp): each scene's reference motion at every frame and every
// method of the chapter measured against it (curtain_runs.cpp), the tables (curtain_tables.cpp), implicit Euler's
// damping of a rigid rotation (rotation.cpp), and in the full run how fast two nearby curtains separate. (The same
// square metre at finer grids is measured by the map, map_sweep.cpp.)
#include "curtain.hpp"

#include "curtain_runs.hpp"

#include "program/interrupt.hpp"
#include "program/output_kinds.hpp"

#include <cstdio>

using namespace cloth;

namespace ch10 {

namespace {

// [sensitivity]
/// How fast two nearby curtains separate: references at 1e-10 and 1e-12 followed past the horizon, to 1 s.
void sensitivity(const std::string& out, const std::string& command) {
  const Scene scene(scene_params(curtain_scenes[0], 20));
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

OutputList curtain_outputs(bool quick) {
  using namespace cloth::output_kinds;
  // The page shows the full run's tables, committed under data/curtain_full: the quick run's are data.
  OutputList files = {{"curtain_scenes.md", fragment, "each scene's motion, strain, phase and reference"},
                      {"curtain_levels.md", data, "each scene's fastest run to plausible, 1 cm and 1 mm"},
                      {"curtain_motion.dat", figure, "each scene's motion at T and over the frames"},
                      {"rotation.md", fragment, "implicit Euler's rate of turning after 1 s against the prediction"},
                      {"rotation.dat", figure, "the rate of turning after each step, measured and predicted"}};
  for (const CurtainScene& c : curtain_scenes) {
    const bool edge_drawn = c.tag != "corners";  // curtain.gp draws the free edge of the hanging curtains
    files = files + OutputList{{"curtain_" + c.tag + ".md", data, c.title + ": every run's errors, energy, strain"},
                               {"curtain_" + c.tag + ".dat", figure, c.title + ": every run's measures"},
                               {"curtain_edge_" + c.tag + ".dat", edge_drawn ? figure : data,
                                c.title + ": the free edge's mean height, reference and runs"},
                               {"curtain_flags_" + c.tag + ".md", fragment, c.title + ": the single run's flags"}};
  }
  if (!quick)
    files = files + OutputList{{"curtain_sensitivity.md", data, "how fast two nearby curtains separate"},
                               {"curtain_sensitivity.dat", data, "the distances of curtain_sensitivity.md"}};
  return files;
}

void curtain_study(bool quick, const std::string& out, const std::string& command) {
  std::vector<SceneResult> results;
  for (const CurtainScene& c : curtain_scenes) {
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
  if (!quick) sensitivity(out, command);
}

}  // namespace ch10
