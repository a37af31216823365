// Chapter 11's scenes: where the cloth starts and what it meets.
#include "scenes.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

using namespace cloth;

namespace ch11 {

const NameTable<SceneKind>& scene_kinds() {
  static const NameTable<SceneKind> table{
      "scene", {{SceneKind::incline, "incline"}, {SceneKind::sphere, "sphere"}, {SceneKind::fold, "fold"}}};
  return table;
}

// The incline: a 10 x 10 sheet of 2 cm spacing and 0.2 kg/m^2 (m = rho_A d^2), free and at rest. The sphere: a
// 20 x 20 sheet of 5 cm spacing and the same fabric, dropped flat. The fold: a 30 x 200 strip of 1 cm spacing, the
// same fabric, standing on the ground. All springs K: the sheet's tensile stiffness is C = 6 K (fabric.hpp), 300
// N/m for the sheets and 120 N/m for the strip; the strip's is lower so that its lighter particles
// (2e-5 kg) keep the same step, and at d = 1 cm its flexion springs match Chapter 10's bending rigidity
// B = 5e-6 N m at 20 /m (k = 16 B / (kappa d^2)^2 = 20 N/m). The fastest mode is near omega = sqrt(10.125 K / m)
// (Chapter 10's lattice bound): 2500 /s on the incline, 1000 /s on the sphere, 3200 /s on the strip, so h = 0.5 ms
// keeps symplectic Euler's h omega at most 1.6. The damping D [N s/m] is a fraction zeta = D / sqrt(2 K m) of a spring's critical damping (its
// two ends, reduced mass m / 2): 0.1 N s/m is zeta = 0.45 on the sphere's sheet. The strip's light particles
// bound D by the explicit step instead: the fastest damping rate is near 10.125 D / m, and h times it must stay
// below 2: D = 0.002 N s/m gives 1000 /s (h c = 0.5) and zeta = 0.07.
std::vector<std::pair<const char*, const char*>> scene_defaults(SceneKind kind) {
  switch (kind) {
    case SceneKind::incline:
      return {{"--grid", "10x10"}, {"--spacing", "0.02"}, {"--mass", "8e-05"}, {"--K", "50"}, {"--damping", "0"},
              {"--pins", "none"},  {"--v0", "0"},         {"--dt", "0.0005"},  {"--t-end", "0.5"}};
    case SceneKind::sphere:
      return {{"--grid", "20x20"}, {"--spacing", "0.05"}, {"--mass", "0.0005"}, {"--K", "50"}, {"--damping", "0.1"},
              {"--pins", "none"},  {"--v0", "0"},         {"--dt", "0.0005"},   {"--t-end", "10"}};
    case SceneKind::fold:
      return {{"--grid", "30x200"}, {"--spacing", "0.01"}, {"--mass", "2e-05"}, {"--K", "20"}, {"--damping", "0.002"},
              {"--pins", "none"},   {"--v0", "0"},         {"--dt", "0.0005"},  {"--t-end", "1.5"}};
  }
  return {};
}

double default_thickness(SceneKind kind) { return kind == SceneKind::fold ? 0.01 : 0.005; }

// [place_scene]
ContactModel place_scene(SceneKind kind, const ContactFlags& flags, SceneParams& params, KeyValues& lines) {
  ContactModel model;
  model.thickness = flags.thickness > 0 ? flags.thickness : default_thickness(kind);
  model.friction = {flags.mu_s, flags.mu_k};
  model.skin = flags.skin;
  const Grid& g = params.grid;
  if (kind == SceneKind::incline) {
    // The plane through the origin with normal (sin theta, 0, cos theta), downhill along +x; the sheet lies on
    // it, its centres one thickness above.
    const double theta = flags.incline_degrees * std::numbers::pi / 180;
    const Eigen::Vector3d n(std::sin(theta), 0, std::cos(theta));
    model.obstacles.emplace_back(HalfSpace{Eigen::Vector3d::Zero(), n});
    params.orientation = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
    params.origin = model.thickness * n;
    lines.emplace_back("incline_angle", format_number(flags.incline_degrees));
  } else if (kind == SceneKind::sphere) {
    // The sphere rests on the ground z = 0 under the sheet's centre; the sheet starts flat, 10 cm above it.
    const double r = flags.sphere_radius, cx = (g.M - 1) * g.d / 2, cy = (g.N - 1) * g.d / 2;
    model.obstacles.emplace_back(HalfSpace{});
    model.obstacles.emplace_back(Sphere{Eigen::Vector3d(cx, cy, r), r});
    params.origin = Eigen::Vector3d(0, 0, 2 * r + 0.1);
    lines.emplace_back("ground_z", "0");
    lines.emplace_back("sphere", format_number(cx) + " " + format_number(cy) + " " + format_number(r) + " " +
                                     format_number(r));
  } else {
    // The strip stands on the ground, its rows j along (0, cos 88, sin 88): 2 degrees off the vertical, enough
    // to choose the side it folds to, too little to topple it before its top has fallen onto its bottom. Its
    // lowest row rests one thickness above the ground.
    model.obstacles.emplace_back(HalfSpace{});
    model.self_collision = true;
    params.orientation = Eigen::AngleAxisd(88 * std::numbers::pi / 180, Eigen::Vector3d::UnitX()).toRotationMatrix();
    params.origin = Eigen::Vector3d(0, 0, model.thickness);
    lines.emplace_back("ground_z", "0");
  }
  try {
    validate(model);
  } catch (const InputError& e) {
    throw InputError(std::string("contact: ") + e.what());
  }
  lines.emplace_back("mu_s", format_number(flags.mu_s));
  lines.emplace_back("mu_k", format_number(flags.mu_k));
  lines.emplace_back("thickness", format_number(model.thickness));
  lines.emplace_back("self_collision", model.self_collision ? "hash" : "none");
  if (model.self_collision) lines.emplace_back("skin", format_number(model.skin));
  return model;
}
// [place_scene]

}  // namespace ch11
