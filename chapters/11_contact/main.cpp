// Chapter 11's single run: a scene that needs contact (a sheet on an inclined plane, a sheet dropped onto a sphere
// on the ground) with any method of the registry, by name; it writes the standard outputs and, in run.txt, the
// geometry a reader needs to check frames.dat against the obstacles.
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "contact/obstacles.hpp"
#include "integrators/contact_implicit_euler.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "model/fabric.hpp"
#include "program/command_line.hpp"
#include "program/method_flags.hpp"
#include "program/output.hpp"
#include "program/progress.hpp"
#include "program/run_outputs.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

using namespace cloth;

namespace {

enum class SceneKind { incline, sphere };

const NameTable<SceneKind>& scene_kinds() {
  static const NameTable<SceneKind> table{"scene", {{SceneKind::incline, "incline"}, {SceneKind::sphere, "sphere"}}};
  return table;
}

// The scene's defaults of the common flags, replacing the report's (the model page allows it). The incline: a
// 10 x 10 sheet of 2 cm spacing and 0.2 kg/m^2, free and at rest; the sphere: a 20 x 20 sheet of 5 cm spacing and
// the same fabric, dropped flat. With K = 50 N/m the fastest mode is near omega = sqrt(16 K / m): 3200 /s on the
// incline's particles, 1300 /s on the sphere's, so h = 0.5 ms keeps symplectic Euler's h omega below 2; the
// small damping slows the drape down (it does not bring it to rest within the default T).
struct SceneDefault {
  const char* flag;
  const char* incline;
  const char* sphere;
};
constexpr SceneDefault scene_defaults[] = {
    {"--grid", "10x10", "20x20"},   {"--spacing", "0.02", "0.05"}, {"--mass", "8e-05", "0.0005"},
    {"--K", "50", "50"},            {"--damping", "0", "0.01"},    {"--pins", "none", "none"},
    {"--v0", "0", "0"},             {"--dt", "0.0005", "0.0005"},  {"--t-end", "0.5", "2"},
};

// --scene, read before the flags are parsed so that its defaults can be set (the last one given; parse refuses a
// flag given twice).
SceneKind scene_of(int argc, char** argv) {
  for (int k = 1; k + 1 < argc; ++k)
    if (std::strcmp(argv[k], "--scene") == 0) {
      try {
        return scene_kinds().parse(argv[k + 1]);
      } catch (const InputError&) {
        return SceneKind::incline;  // parse reports the bad name
      }
    }
  return SceneKind::incline;
}

double above_zero(const std::string& text) {
  const double x = parse_number(text);
  if (!(x > 0)) throw InputError(text + ": expected a number > 0");
  return x;
}

double at_least_zero(const std::string& text) {
  const double x = parse_number(text);
  if (!(x >= 0)) throw InputError(text + ": expected a number >= 0");
  return x;
}

}  // namespace

int main(int argc, char** argv) {
  std::string method_name = "symplectic_euler";
  SceneKind kind = SceneKind::incline;
  double incline_degrees = 30, mu_s = 0.3, mu_k = 0.2, thickness = 0.005;
  double sphere_radius = 0.3, drop = 0.1;
  NewtonFlags newton;
  IterationFlags iterations;
  CommandLine cli("ch11_contact",
                  "Chapter 11: one run of a scene with contact (incline or sphere) with any method of the registry.\n"
                  "implicit_euler enforces contact inside conjugate gradients (Baraff and Witkin's filter), XPBD as\n"
                  "inequality constraints in its substeps, every other method by a correction after each step.");
  const SceneKind chosen = scene_of(argc, argv);
  for (const SceneDefault& d : scene_defaults) cli.set_default(d.flag, chosen == SceneKind::incline ? d.incline : d.sphere);
  std::string names;
  for (const std::string& name : method_names()) names += (names.empty() ? "" : ", ") + name;
  cli.add_value("--scene", "incline|sphere", "the scene (default incline); its defaults of the flags above",
                [&](const std::string& s) { kind = scene_kinds().parse(s); });
  cli.add_value("--method", "NAME", "a method of the registry (" + names + "; default symplectic_euler)",
                [&](const std::string& s) { method_name = s; });
  cli.add_value("--incline-angle", "DEG", "incline scene: the plane's angle [degrees], in [0, 80] (default 30)",
                [&](const std::string& s) {
                  incline_degrees = parse_number(s);
                  if (!(incline_degrees >= 0 && incline_degrees <= 80))
                    throw InputError(s + ": expected an angle in [0, 80] degrees");
                });
  cli.add_value("--mu-s", "X", "static friction coefficient, >= 0 (default 0.3)",
                [&](const std::string& s) { mu_s = at_least_zero(s); });
  cli.add_value("--mu-k", "Y", "kinetic friction coefficient, in [0, mu_s] (default 0.2)",
                [&](const std::string& s) { mu_k = at_least_zero(s); });
  cli.add_value("--thickness", "h", "the cloth's thickness [m], > 0 (default 0.005)",
                [&](const std::string& s) { thickness = above_zero(s); });
  cli.add_value("--sphere-radius", "r", "sphere scene: the sphere's radius [m], > 0 (default 0.3)",
                [&](const std::string& s) { sphere_radius = above_zero(s); });
  newton.add_to(cli);
  iterations.add_to(cli);
  return run_program(cli.program(), [&] {
    Options opt = cli.parse(argc, argv);
    if (mu_k > mu_s)
      throw InputError("--mu-k " + format_number(mu_k) + ": expected at most --mu-s = " + format_number(mu_s) +
                       " (sliding friction never exceeds sticking friction)");
    ContactModel model;
    model.thickness = thickness;
    model.friction = {mu_s, mu_k};
    const Grid& g = opt.scene.grid;
    KeyValues lines;
    if (kind == SceneKind::incline) {
      // The plane through the origin with normal (sin theta, 0, cos theta), downhill along +x; the sheet lies on
      // it, its centres one thickness above.
      const double theta = incline_degrees * std::numbers::pi / 180;
      const Eigen::Vector3d n(std::sin(theta), 0, std::cos(theta));
      model.obstacles.emplace_back(HalfSpace{Eigen::Vector3d::Zero(), n});
      opt.scene.orientation = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
      opt.scene.origin = thickness * n;
      lines.emplace_back("incline_angle", format_number(incline_degrees));
    } else {
      // The sphere rests on the ground z = 0 under the sheet's centre; the sheet starts flat, `drop` above it.
      const double cx = (g.M - 1) * g.d / 2, cy = (g.N - 1) * g.d / 2;
      model.obstacles.emplace_back(HalfSpace{});
      model.obstacles.emplace_back(Sphere{Eigen::Vector3d(cx, cy, sphere_radius), sphere_radius});
      opt.scene.origin = Eigen::Vector3d(0, 0, 2 * sphere_radius + drop);
      lines.emplace_back("ground_z", "0");
      lines.emplace_back("sphere", format_number(cx) + " " + format_number(cy) + " " + format_number(sphere_radius) +
                                       " " + format_number(sphere_radius));
    }
    try {
      validate(model);
    } catch (const InputError& e) {
      throw InputError(std::string("contact: ") + e.what());
    }
    lines.emplace_back("mu_s", format_number(mu_s));
    lines.emplace_back("mu_k", format_number(mu_k));
    lines.emplace_back("thickness", format_number(thickness));

    const Method* method = nullptr;
    try {
      method = &find_method(method_name);
    } catch (const InputError& e) {
      throw InputError(std::string("--method: ") + e.what());
    }
    const Scene scene(opt.scene);
    ForceField field(scene);
    std::unique_ptr<Stepper> stepper;
    if (method->name == "implicit_euler") {
      if (!newton.first_given().empty())
        throw InputError(newton.first_given() + ": implicit_euler with contact is Baraff and Witkin's one-iteration "
                                                "step with filtered conjugate gradients, which has no such setting");
      stepper = std::make_unique<ContactImplicitEuler>(field, model);
      lines.emplace_back("contact", "filtered_cg");
    } else {
      MethodSettings settings;
      const std::vector<const Method*> implicit = newton_methods();
      if (std::find(implicit.begin(), implicit.end(), method) != implicit.end())
        settings.newton = newton.settings_for(scene);
      else if (!newton.first_given().empty())
        throw InputError(newton.first_given() + ": " + method->name + " has no Newton iteration to set");
      iterations.apply(*method, settings);
      try {
        stepper = std::make_unique<ContactStepper>(method->stepper(field, settings), model);
      } catch (const InputError& e) {
        throw InputError("--method " + method->name + ": " + e.what());
      }
      lines.emplace_back("contact",
                         method->family == MethodFamily::position_based ? "inequality_constraints" : "after_step");
    }
    prepare_outputs(opt.run.out_dir, run_output_names());

    RunSettings run = opt.run;
    run.progress = terminal_progress(cli.program());
    const RunResult result = simulate(*stepper, run);
    // How far into the shell the recorded frames go (pinned particles included: there are none in these scenes).
    double deepest = -thickness;
    for (const Frame& f : result.frames) deepest = std::max(deepest, deepest_penetration(model, f.positions));
    lines.emplace_back("deepest_penetration_frames", format_number(deepest, 3));
    return finish_run(result, *stepper, run, cli.program(), lines);
  });
}
