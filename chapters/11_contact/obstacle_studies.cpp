// The obstacle studies of Chapter 11: the incline against its closed form, and the drape over the sphere with
// every family of method, each kept out of the obstacles its own way.
#include "studies.hpp"

#include "base/format_number.hpp"
#include "integrators/contact_dirk.hpp"
#include "integrators/contact_implicit_euler.hpp"
#include "integrators/contact_stepper.hpp"
#include "integrators/implicit_tableaus.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

using namespace cloth;

namespace ch11 {

namespace {

constexpr double g = 9.81;

// The methods of the page's table, one per family, by the name the table gives them.
struct StudyMethod {
  const char* label;   // the table's name
  const char* family;  // how it keeps out of the obstacles
  double h;            // its step on the sphere [s]
};
constexpr StudyMethod sphere_methods[] = {
    {"symplectic_euler", "explicit: corrected after the step", 5e-4},
    {"rk4", "explicit: corrected after the step", 5e-4},
    {"implicit_euler (one iteration)", "implicit: filtered CG", 1e-2},
    {"implicit_euler (Newton)", "implicit: filtered CG, each iteration", 1e-2},
    {"sdirk2", "implicit Runge-Kutta: corrected after the step", 1e-2},
    {"local_global", "local/global: corrected after the step", 1e-2},
    {"xpbd", "position based: inequality constraints", 1e-2},
};

std::unique_ptr<Stepper> study_stepper(const std::string& label, ForceField& field, const ContactModel& model) {
  if (label == "implicit_euler (one iteration)") return std::make_unique<ContactImplicitEuler>(field, model);
  if (label == "implicit_euler (Newton)") return std::make_unique<ContactImplicitEuler>(field, model, FilteredNewton{50, 1e-6});
  return std::make_unique<ContactStepper>(make_stepper(label, field), model);
}

// Mean displacement of the sheet down the slope.
double mean_downhill(const Vector& x, const Vector& x0, double theta) {
  const Eigen::Vector3d down(std::cos(theta), 0, -std::sin(theta));
  double sum = 0;
  for (Eigen::Index s = 0; s < x.size() / 3; ++s) sum += (x - x0).segment<3>(3 * s).dot(down);
  return sum / static_cast<double>(x.size() / 3);
}

}  // namespace

// [incline_study]
void incline_study(const Study& study) {
  MarkdownTable table({"method", "angle [deg]", "tan / mu_s", "measured a [m/s^2]", "g (sin - mu_k cos) [m/s^2]",
                       "measured / closed form - 1", "deepest [% of thickness]"}, "lrrrrrr");
  std::string curves = "# t mean_downhill_displacement closed_form (symplectic Euler, per angle, one block each)\n";
  const double T = 0.5;
  for (const double degrees : {std::atan(0.9 * 0.3) * 180 / std::numbers::pi, 30.0}) {
    ContactFlags flags;
    flags.incline_degrees = degrees;
    const double theta = degrees * std::numbers::pi / 180;
    // Coulomb: at rest it stays at rest while tan theta <= mu_s; sliding, mu_k brakes it.
    const double a = std::tan(theta) <= 0.3 ? 0.0 : g * (std::sin(theta) - 0.2 * std::cos(theta));
    for (const char* label : {"symplectic_euler", "rk4", "implicit_euler (one iteration)", "xpbd", "small_steps"}) {
      const BuiltScene b = build_scene(SceneKind::incline, flags);
      const auto stepper = study_stepper(label, *b.field, b.model);
      const SteppedRun run = step_run(*stepper, b, 5e-4, T, 50);
      const double s = mean_downhill(run.x, b.scene->initial_positions(), theta);
      const double measured = 2 * s / (T * T);  // s = a T^2 / 2 from rest
      table.add_row({label, format_fixed(degrees, 2), format_fixed(std::tan(theta) / 0.3, 2), format_number(measured, 4),
                     format_number(a, 4), a > 0 ? format_number(measured / a - 1, 2) : "(at rest)",
                     format_number(std::max(0.0, run.deepest) / b.model.thickness * 100, 2)});
      if (std::string(label) != "symplectic_euler") continue;
      for (const Frame& f : run.frames)
        curves += format_number(f.t, 6) + " " + format_number(mean_downhill(f.positions, b.scene->initial_positions(), theta), 8) +
                  " " + format_number(0.5 * a * f.t * f.t, 8) + "\n";
      curves += "\n\n";
      if (degrees == 30.0) write_scene_frames(study, "incline", b, run.frames);
    }
  }
  write_text(study.dir + "/incline.dat", curves);
  write_table_fragment(study.dir + "/incline.md", table, study.command);
}
// [incline_study]

// [sphere_study]
// Every family on a 10 x 10 sheet of the scene's fabric over a sphere of radius 0.15 m, to T = 4 s; then the
// scene itself (20 x 20 over 0.3 m, T = 10 s) with symplectic Euler for the animation.
void sphere_study(const Study& study) {
  MarkdownTable table({"method", "keeps out by", "h [s]", "deepest after any step [% of thickness]",
                       "kinetic energy at T / peak", "processor seconds"}, "llrrrr");
  const double T = 4;
  const Grid small{10, 10, 0.05};
  ContactFlags small_sphere;
  small_sphere.sphere_radius = 0.15;
  std::string energy = "# t kinetic/peak, one block per method in the table's order\n";
  for (const StudyMethod& m : sphere_methods) {
    const BuiltScene b = build_scene(SceneKind::sphere, small_sphere, &small);
    const auto stepper = study_stepper(m.label, *b.field, b.model);
    const SteppedRun run = step_run(*stepper, b, m.h, T, 60);
    double peak = 0;
    for (const double k : run.kinetic) peak = std::max(peak, k);
    const std::string ratio = run.ok ? format_number(run.kinetic.back() / peak, 2) : "failed at t = " + format_number(run.t.empty() ? 0 : run.t.back(), 3) + " s";
    table.add_row({m.label, m.family, format_number(m.h), format_number(std::max(0.0, run.deepest) / b.model.thickness * 100, 2),
                   ratio, format_fixed(run.seconds, 2)});
    energy += "# " + std::string(m.label) + "\n";
    const std::size_t stride = std::max<std::size_t>(1, run.t.size() / 400);
    for (std::size_t k = 0; k < run.t.size(); k += stride)
      energy += format_number(run.t[k], 6) + " " + format_number(std::max(run.kinetic[k] / peak, 1e-16), 6) + "\n";
    energy += "\n\n";
  }
  write_text(study.dir + "/sphere_energy.dat", energy);
  write_table_fragment(study.dir + "/sphere.md", table, study.command);
  const BuiltScene b = build_scene(SceneKind::sphere, ContactFlags{});
  ContactStepper stepper(make_stepper("symplectic_euler", *b.field), b.model);
  const SteppedRun run = step_run(stepper, b, 5e-4, 10, 50);
  double peak = 0;
  for (const double k : run.kinetic) peak = std::max(peak, k);
  write_text_fragment(study.dir + "/sphere_rest.md",
                      "kinetic energy at T = 10 s: " + format_number(run.kinetic.back() / peak, 2) +
                          " of its peak; deepest after any step: " +
                          format_number(std::max(0.0, run.deepest) / b.model.thickness * 100, 2) + " % of the thickness");
  write_scene_frames(study, "sphere", b, run.frames);
}
// [sphere_study]

// [sdirk2_rest]
// SDIRK2 corrected after the step on the small drape, at three steps: how much of its peak kinetic energy the sheet
// keeps at T = 4 s, its fastest particle's velocity then, and how fast that particle actually moves over the next
// step. A velocity the particle does not move with is the mark of a state the correction and the stages disagree on.
void sdirk2_rest_study(const Study& study) {
  MarkdownTable table({"h [s]", "kinetic energy at 4 s / peak", "fastest particle's speed |v| [m/s]",
                       "its displacement over the next step / h [m/s]", "its distance from the sphere's shell [mm]"},
                      "rrrrr");
  const Grid small{10, 10, 0.05};
  ContactFlags small_sphere;
  small_sphere.sphere_radius = 0.15;
  for (const double h : {1e-2, 5e-3, 2.5e-3}) {
    const BuiltScene b = build_scene(SceneKind::sphere, small_sphere, &small);
    const auto stepper = study_stepper("sdirk2", *b.field, b.model);
    SteppedRun run = step_run(*stepper, b, h, 4, 1);
    double peak = 0;
    for (const double k : run.kinetic) peak = std::max(peak, k);
    Eigen::Index fastest = 0;
    for (Eigen::Index s = 0; s < run.v.size() / 3; ++s)
      if (run.v.segment<3>(3 * s).norm() > run.v.segment<3>(3 * fastest).norm()) fastest = s;
    const Eigen::Vector3d before = run.x.segment<3>(3 * fastest), speed = run.v.segment<3>(3 * fastest);
    const bool stepped = run.ok && stepper->step(h, run.x, run.v);
    const double shell = surface_point(b.model.obstacles.back(), before).phi - b.model.thickness;
    table.add_row({format_number(h), format_number(run.kinetic.back() / peak, 2), format_number(speed.norm(), 3),
                   stepped ? format_number((run.x.segment<3>(3 * fastest) - before).norm() / h, 3) : "failed",
                   format_fixed(1e3 * shell, 1)});
  }
  write_table_fragment(study.dir + "/sdirk2_rest.md", table, study.command);
}
// [sdirk2_rest]

// sdirk2_stages.md: SDIRK2 on the same drape at 10 ms, corrected after the step against the filter inside each
// stage's solve (ContactDirk), with one iteration or Newton's per stage: the kinetic energy over its peak at 2, 4,
// 6 and 8 s, the largest from 6 to 8 s (the level it hovers at, which one instant need not show), and the deepest
// penetration after any step. Two more rows run the single iteration with half and twice the scene's damping D.
void sdirk2_stages_study(const Study& study) {
  MarkdownTable table({"SDIRK2, h = 10 ms", "E_k / peak at 2 s", "at 4 s", "at 6 s", "at 8 s", "largest, 6 to 8 s",
                       "deepest [% of thickness]"}, "lrrrrrr");
  const Grid small{10, 10, 0.05};
  ContactFlags small_sphere;
  small_sphere.sphere_radius = 0.15;
  const double h = 1e-2;
  const std::pair<const char*, double> rows[] = {
      {"corrected after the step", 0}, {"filtered in each stage, one iteration", 0},
      {"filtered in each stage, Newton", 0}, {"filtered in each stage, one iteration, D = 0.05 N s/m", 0.05},
      {"filtered in each stage, one iteration, D = 0.2 N s/m", 0.2}};
  for (const auto& [label, damping] : rows) {
    BuiltScene b = build_scene(SceneKind::sphere, small_sphere, &small);
    if (damping > 0) {  // the scene's D (0.1 N s/m) replaced
      b.params.damping = damping;
      b.scene = std::make_unique<Scene>(b.params);
      b.field = std::make_unique<ForceField>(*b.scene);
    }
    const std::string name = label;
    std::unique_ptr<Stepper> stepper;
    if (name.starts_with("corrected"))
      stepper = std::make_unique<ContactStepper>(make_stepper("sdirk2", *b.field), b.model);
    else
      stepper = std::make_unique<ContactDirk>(*b.field, builtin_implicit_tableau("sdirk2"), b.model,
                                              name.ends_with("Newton") ? FilteredNewton{50, 1e-6} : FilteredNewton{});
    const SteppedRun run = step_run(*stepper, b, h, 8, 1);
    double peak = 0, late = 0;
    for (std::size_t k = 0; k < run.kinetic.size(); ++k) {
      peak = std::max(peak, run.kinetic[k]);
      if (run.t[k] > 6 + h / 2) late = std::max(late, run.kinetic[k]);
    }
    std::vector<std::string> row{label};
    for (const int seconds : {2, 4, 6, 8}) {
      const auto k = static_cast<std::size_t>(std::lround(seconds / h)) - 1;
      row.push_back(k < run.kinetic.size() ? format_number(run.kinetic[k] / peak, 2) : "failed");
    }
    row.push_back(run.ok ? format_number(late / peak, 2) : "failed");
    row.push_back(format_number(100 * std::max(0.0, run.deepest) / b.model.thickness, 2));
    table.add_row(row);
  }
  write_table_fragment(study.dir + "/sdirk2_stages.md", table, study.command);
}

}  // namespace ch11
