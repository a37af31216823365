// Chapter 11's program: one run of a scene that needs contact (a sheet on an inclined plane, a sheet dropped onto a
// sphere on the ground, a strip folding onto itself) with any method of the registry, by name; it writes the
// standard outputs and, in run.txt, the geometry a reader needs to check frames.dat against the obstacles. With
// --report-runs it makes the page's figures and tables instead.
#include "report.hpp"
#include "scenes.hpp"
#include "steppers.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/simulate.hpp"
#include "program/command_line.hpp"
#include "program/output.hpp"
#include "program/output_spec.hpp"
#include "program/progress.hpp"

#include <algorithm>
#include <cstring>
#include <string>

using namespace cloth;
using namespace ch11;

namespace {

// --scene, read before the flags are parsed so that its defaults can be set (parse refuses a flag given twice).
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

// The scene's own flags.
void add_contact_flags(CommandLine& cli, SceneKind& kind, ContactFlags& f) {
  cli.add_value("--scene", "incline|sphere|fold", "the scene (default incline); its defaults of the flags above",
                [&](const std::string& s) { kind = scene_kinds().parse(s); });
  cli.add_value("--incline-angle", "DEG", "incline scene: the plane's angle [degrees], in [0, 80] (default 30)",
                [&](const std::string& s) {
                  f.incline_degrees = parse_number(s);
                  if (!(f.incline_degrees >= 0 && f.incline_degrees <= 80))
                    throw InputError(s + ": expected an angle in [0, 80] degrees");
                });
  cli.add_value("--mu-s", "X", "static friction coefficient, >= 0 (default 0.3)",
                [&](const std::string& s) { f.mu_s = at_least_zero(s); });
  cli.add_value("--mu-k", "Y", "kinetic friction coefficient, in [0, mu_s] (default 0.2)",
                [&](const std::string& s) { f.mu_k = at_least_zero(s); });
  cli.add_value("--thickness", "h", "the cloth's thickness [m], > 0 (default 0.005; fold: 0.01)",
                [&](const std::string& s) { f.thickness = above_zero(s); });
  cli.add_value("--sphere-radius", "r", "sphere scene: the sphere's radius [m], > 0 (default 0.3)",
                [&](const std::string& s) { f.sphere_radius = above_zero(s); });
  cli.add_value("--skin", "s",
                "fold scene: self-collision's skin, a fraction of the thickness in (0, 1] (default 0.25): the "
                "pairs within (1 + 2 s) thickness are kept until a particle moves s thickness beyond the common motion",
                [&](const std::string& s) {
                  f.skin = parse_number(s);
                  if (!(f.skin > 0 && f.skin <= 1)) throw InputError(s + ": expected a fraction in (0, 1]");
                });
}

// The single run: place the scene, choose how the method keeps out of the obstacles, step, write.
int single_run(Options& opt, SceneKind kind, const ContactFlags& flags, const std::string& method_name,
               const NewtonFlags& newton, const IterationFlags& iterations, const std::string& program) {
  if (flags.mu_k > flags.mu_s)
    throw InputError("--mu-k " + format_number(flags.mu_k) + ": expected at most --mu-s = " +
                     format_number(flags.mu_s) + " (sliding friction never exceeds sticking friction)");
  KeyValues lines;
  const ContactModel model = place_scene(kind, flags, opt.scene, lines);
  const Method* method = nullptr;
  try {
    method = &find_method(method_name);
  } catch (const InputError& e) {
    throw InputError(std::string("--method: ") + e.what());
  }
  const Scene scene(opt.scene);
  ForceField field(scene);
  const std::unique_ptr<Stepper> stepper = contact_stepper(*method, field, model, newton, iterations, lines);
  prepare_declared_outputs(opt.run.out_dir, run_output_specs(), report_outputs());
  RunSettings run = opt.run;
  run.progress = terminal_progress(program);
  const RunResult result = simulate(*stepper, run);
  // How far into the shell the recorded frames go, and (with self-collision) how close two layers came.
  double deepest = -model.thickness;
  for (const Frame& f : result.frames) deepest = std::max(deepest, deepest_penetration(model, f.positions));
  lines.emplace_back("deepest_penetration_frames", format_number(deepest, 3));
  if (const auto* wrapped = dynamic_cast<const ContactStepper*>(stepper.get()); wrapped && wrapped->self_collision()) {
    SelfCollision check(scene.initial_positions(), model.thickness);
    double closest = model.thickness;
    for (const Frame& f : result.frames) closest = std::min(closest, check.closest_distance(f.positions, 2));
    const SelfCollisionWork& work = wrapped->self_collision()->work();
    lines.emplace_back("closest_self_distance_frames", format_number(closest, 4));
    lines.emplace_back("self_collision_builds", std::to_string(work.builds));
    lines.emplace_back("self_collision_passes", std::to_string(work.passes));
    lines.emplace_back("self_collision_candidates", std::to_string(work.pairs_found));
    lines.emplace_back("self_collision_corrected", std::to_string(work.pairs_corrected));
    lines.emplace_back("self_collision_seconds", format_number(work.seconds, 3));
    lines.emplace_back("self_collision_pass_seconds", format_number(work.pass_seconds, 3));
  }
  return finish_run(result, *stepper, run, program, lines);
}

}  // namespace

int main(int argc, char** argv) {
  std::string method_name = "symplectic_euler";
  SceneKind kind = SceneKind::incline;
  ContactFlags flags;
  bool report = false;
  NewtonFlags newton;
  IterationFlags iterations;
  CommandLine cli("ch11_contact",
                  "Chapter 11: one run of a scene with contact (incline, sphere or fold) with any method of the\n"
                  "registry. implicit_euler enforces contact inside conjugate gradients (Baraff and Witkin's filter,\n"
                  "one Newton iteration per step unless --newton full, --newton-tol or --newton-max-iter asks for\n"
                  "more; not in the fold scene), XPBD as inequality constraints in its substeps, every other method\n"
                  "by a correction after each step; the fold scene adds self-collision. --report-runs makes the\n"
                  "chapter's figures and tables.");
  for (const auto& [flag, value] : scene_defaults(scene_of(argc, argv))) cli.set_default(flag, value);
  std::string names;
  for (const std::string& name : method_names()) names += (names.empty() ? "" : ", ") + name;
  add_contact_flags(cli, kind, flags);
  cli.add_value("--method", "NAME", "a method of the registry (" + names + "; default symplectic_euler)",
                [&](const std::string& s) { method_name = s; });
  cli.add_switch("--report-runs", "run the chapter's studies into --out (figures' data and the page's tables)",
                 [&] { report = true; });
  add_report_flags(cli);
  newton.add_to(cli, NewtonVariant::full, ch11::filtered_newton_default);
  iterations.add_to(cli);
  cli.declare_outputs([&](const Options&) { return report ? report_outputs() : run_output_specs(); });
  return run_program(cli.program(), [&] {
    Options opt = cli.parse(argc, argv);
    if (report) return run_report(argc, argv, opt);
    if (std::find(opt.given.begin(), opt.given.end(), "--quick") != opt.given.end())
      throw InputError("--quick: a setting of --report-runs, which was not given");
    return single_run(opt, kind, flags, method_name, newton, iterations, cli.program());
  });
}
