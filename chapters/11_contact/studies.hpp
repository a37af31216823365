// Chapter 11's studies, one file each, and the stepping loop they share: every accepted step is checked against
// the obstacles, frames are kept for the figures and animations.
#pragma once

#include "scenes.hpp"

#include "contact/obstacles.hpp"
#include "integrators/stepper.hpp"
#include "integrators/simulate.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ch11 {

/// Where a study writes, the command that measured it, and whether it runs its quick version.
struct Study {
  std::string dir;
  std::string command;
  bool quick = false;
};

/// A scene built from the chapter's defaults with `flags`, ready to step.
struct BuiltScene {
  cloth::SceneParams params;
  cloth::ContactModel model;
  std::unique_ptr<cloth::Scene> scene;
  std::unique_ptr<cloth::ForceField> field;
  cloth::KeyValues geometry;  ///< run.txt's lines of the obstacles (place_scene), for the animations to draw them
};
[[nodiscard]] BuiltScene build_scene(SceneKind kind, const ContactFlags& flags, const cloth::Grid* grid = nullptr);

/// The fold the self-collision studies run: a 30 x 200 strip of 1 cm spacing to 1.5 s, or with `--quick` a 30 x 100
/// strip to 1 s (the plots' version), stepped at h = 0.5 ms.
struct FoldStudyRun {
  cloth::Grid grid;
  double T, h;
};
[[nodiscard]] FoldStudyRun fold_study_run(const Study& study);

/// What a stepped run gives the studies.
struct SteppedRun {
  bool ok = true;
  std::string failure;
  double deepest = -1;         ///< largest penetration (thickness - phi) after any accepted step [m]
  double seconds = 0;          ///< processor time of the steps (the calling thread's, program/timing.hpp)
  long long steps = 0;
  std::vector<double> t, kinetic;  ///< after every step
  std::vector<cloth::Frame> frames;
  cloth::Vector x, v;
};

/// Steps `stepper` from the scene's start with step h to T, keeping `frames` + 1 evenly spaced frames and calling
/// `after_step` (when set) on each accepted state.
SteppedRun step_run(cloth::Stepper& stepper, const BuiltScene& built, double h, double T, int frames,
                    const std::function<void(const cloth::Vector&)>& after_step = {});

/// Writes the frames of a run of `built` as `scene`_frames.dat and, beside them, the obstacles they meet as
/// `scene`_geometry.txt, in run.txt's lines (`ground_z = z`, `sphere = cx cy cz r`, `incline_angle = deg`, ...).
void write_scene_frames(const Study& study, const std::string& scene, const BuiltScene& built,
                        const std::vector<cloth::Frame>& frames);

void incline_study(const Study& study);
void sphere_study(const Study& study);
void sdirk2_rest_study(const Study& study);
void sdirk2_stages_study(const Study& study);
void fold_study(const Study& study);
void skin_study(const Study& study);
void hash_benchmark(const Study& study);
void adaptive_skin_study(const Study& study);
void patch_hierarchy_study(const Study& study);
void edge_crossing_study(const Study& study);

}  // namespace ch11
