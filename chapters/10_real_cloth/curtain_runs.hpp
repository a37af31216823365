// The pieces of Chapter 10's study of cloth that moves (curtain.hpp): its scenes and methods (here), a scene's
// reference and every method's runs measured against it (curtain_runs.cpp), the tables and data written from them
// (curtain_tables.cpp), and implicit Euler's damping of a rigid rotation (rotation.cpp).
#pragma once

#include "study.hpp"

#include "analysis/reference_trajectory.hpp"
#include "analysis/trajectory_measures.hpp"
#include "program/fragment.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace ch10 {

inline constexpr double frame_rate = 60;  ///< the reference and the measures see the cloth every 1/60 s
inline constexpr double curtain_K = 1e5;  ///< the chapter's stiff fabric: one K for every family [N/m]

// [curtain_scenes]
/// A scene of the study: the chapter's fabric (ch10::fabric: 0.95 m square, 0.25 kg/m^2, D = 0.01, released from
/// rest) hung by `pins`, started turning at `swing` rad/s about the edge j = N-1, followed for T seconds.
struct CurtainScene {
  std::string tag;    ///< names its files
  std::string title;  ///< names it on the page
  cloth::PinSet pins;
  double swing;
  double T;
};

inline const std::vector<CurtainScene> curtain_scenes = {
    {"curtain", "the curtain, released flat", cloth::PinSet::edge, 0.0, 0.6},
    {"swing", "the curtain thrown down at 4 rad/s", cloth::PinSet::edge, -4.0, 0.8},
    {"corners", "the sheet hung by its four corners", cloth::PinSet::corners, 0.0, 0.5},
};
// [curtain_scenes]

// [curtain_methods]
/// A method of the study and its steps [s]; no steps: 95 % of its stable step on the flat fabric (Chapter 7),
/// shortened to a whole number of steps per frame. Adding a method of the registry to the study is one line here.
struct MethodRow {
  std::string key;  ///< as ch10::make_method takes it
  std::vector<double> steps;
  std::size_t quick_steps = 3;  ///< how many of the steps the quick run tries (full Newton: seconds per run)
};
inline const std::vector<double> frame_steps = {1.0 / 30, 1.0 / 60, 1.0 / 120};
inline const std::vector<MethodRow> curtain_methods = {
    {"symplectic_euler", {}},
    {"rk4", {}},
    {"implicit_euler/one/cg", frame_steps},
    {"implicit_euler/cg", frame_steps, 1},
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
  cloth::TrajectoryError error;
  double energy_lost = NAN;  ///< beyond the reference at T, as a fraction of the reference's peak kinetic energy
  double strain = 0;         ///< the largest spring strain over the frames
  double minimum = NAN;      ///< the first minimum of the free edge's mean height [s]
  std::vector<double> t, edge;
};

/// A scene's reference motion, its measures, and every method's runs on the n x n grid.
struct SceneResult {
  CurtainScene scene;
  int n = 20;
  cloth::ReferenceTrajectory reference;
  double check = -1;  ///< largest distance over the frames to the reference at the tighter tolerance, or -1
  double check_tolerance = 0;
  cloth::TrajectoryError motion;
  double peak_kinetic = 0, reference_strain = 0, reference_minimum = NAN;
  std::vector<double> t, edge;
  std::vector<CurtainRun> runs;
};

/// The scene's parameters on the n x n grid.
cloth::SceneParams scene_params(const CurtainScene& c, int n);
/// The common flags that give the scene to a single-run program at n x n.
std::string scene_flags(const CurtainScene& c, int n);

/// The scene's reference, its measures and every method's runs on the n x n grid; `quick`: the quick run's
/// settings (a looser reference, unchecked, and fewer full Newton runs).
SceneResult measure_scene(const CurtainScene& c, int n, bool quick);

/// A length as the tables print it: in m from 10 cm, in cm from 1 mm, in mm from 1 µm.
std::string metres(double x);

/// The table of the scenes: their motion, strain, phase and reference (curtain_scenes.md).
cloth::MarkdownTable scenes_table(const std::vector<SceneResult>& results);
/// One scene's runs: errors, energy, strain, phase, and whether each reached 1 cm and 1 mm (curtain_TAG.md).
cloth::MarkdownTable runs_table(const SceneResult& r);
/// For each scene and level, the fastest run that reached it, or that standing still meets it (curtain_levels.md).
cloth::MarkdownTable levels_table(const std::vector<SceneResult>& results);
/// One scene's runs as data, and the free edge's mean height of the reference and every run (curtain_TAG.dat,
/// curtain_edge_TAG.dat).
void write_runs_data(const std::string& out, const SceneResult& r);

/// Implicit Euler's damping of a rigid rotation, measured against the page's prediction (rotation.md,
/// rotation.dat).
void rotation_study(const std::string& out, const std::string& command);

}  // namespace ch10
