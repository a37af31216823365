// Chapter 11's three scenes: a sheet on an inclined plane, a sheet dropped onto a sphere on the ground, and a long
// strip falling onto the ground and folding onto itself; their defaults and their obstacles.
#pragma once

#include "contact/obstacles.hpp"
#include "model/scene.hpp"
#include "base/name_table.hpp"
#include "program/run_outputs.hpp"

namespace ch11 {

enum class SceneKind { incline, sphere, fold };

[[nodiscard]] const cloth::NameTable<SceneKind>& scene_kinds();

/// The scene's own flags (the common ones are the scene's parameters).
struct ContactFlags {
  double incline_degrees = 30;
  double mu_s = 0.3;
  double mu_k = 0.2;
  double thickness = 0;  ///< 0: the scene's default (5 mm for the sheets, 1 cm for the strip)
  double sphere_radius = 0.3;
  double skin = 0.25;  ///< self-collision's skin, a fraction of the thickness (fold scene)
};

/// The scene's defaults of the common flags, as `--help` prints them (the model page allows a scene's defaults to
/// replace the report's): pairs of flag and value.
[[nodiscard]] std::vector<std::pair<const char*, const char*>> scene_defaults(SceneKind kind);

/// The scene's thickness when `--thickness` is not given.
[[nodiscard]] double default_thickness(SceneKind kind);

/// Places the cloth of `params` for the scene (orientation and origin) and returns the obstacles, friction and
/// thickness; `lines` receives run.txt's geometry keys (incline_angle, or ground_z and sphere; mu_s, mu_k,
/// thickness). Throws InputError naming what is out of range.
cloth::ContactModel place_scene(SceneKind kind, const ContactFlags& flags, cloth::SceneParams& params,
                                cloth::KeyValues& lines);

}  // namespace ch11
