// Chapter 10's measuring tools (see study.hpp).
#include "study.hpp"

#include "integrators/configuration.hpp"
#include "integrators/method_registry.hpp"
#include "analysis/trajectory_measures.hpp"
#include "model/fabric.hpp"
#include "program/interrupt.hpp"
#include "program/method_flags.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <stdexcept>

using namespace cloth;

namespace ch10 {

SceneParams fabric(int n, double K) {
  FabricMeasurements cloth;  // 0.25 kg/m^2, D = 0.01
  SceneParams p = fabric_scene(cloth, {0.95, n, 20.0});
  p.stiffness = K;  // one K for every family, as in the scene the chapter starts from
  p.flexion_stiffness.reset();
  return p;
}

namespace {

// The chapter's settings for a method given by its one name (integrators/configuration.hpp): the Newton matrix by
// the book's default rule unless the name chose it. From the flat sheet at rest a frame-sized step takes Newton
// through compressed, indefinite states, where its line search on the incremental potential may backtrack
// (Chapter 4). The cap of 1000 is a safeguard against a stall, not a budget: the iterations a step needs grow like
// h^2/m (ch10.md, "Where full Newton's iterations go"), and on 80 x 80 the first 1/30 s step of the curtain needs
// more than 100 of them (the whole 0.3 s, 562 at K = 1e5; at 1/120 s and K = 1e4 one step did). Its tolerance, 1e-6 relative in the velocity, is a position error
// below 1e-6 h, far under every error this chapter measures.
Configuration configuration(const std::string& name) {
  Configuration c = parse_configuration(name);
  NewtonSettings& newton = c.settings.newton;
  newton.treatment = c.jacobian ? *c.jacobian : default_treatment(newton.solver, false);
  newton.max_iterations = 1000;
  newton.tolerance = 1e-6;
  newton.cg_tolerance = 1e-8;
  return c;
}

}  // namespace

std::unique_ptr<Stepper> make_method(const std::string& name, ForceField& field) {
  const Configuration c = configuration(name);
  return make_stepper(c.method, field, c.settings);
}

bool is_explicit(const std::string& name) {
  const MethodFamily family = find_method(parse_configuration(name).method).family;
  return family == MethodFamily::explicit_runge_kutta || family == MethodFamily::partitioned ||
         family == MethodFamily::embedded_runge_kutta;
}

std::string label(const std::string& name) { return configuration_name(parse_configuration(name)); }

namespace {

Run run_once(const Scene& scene, const std::string& method, double T, long long steps) {
  ForceField field(scene);
  auto stepper = make_method(method, field);
  Run r;
  r.x = scene.initial_positions();
  Vector v = scene.initial_velocities();
  const double h = T / static_cast<double>(steps);
  const double t0 = thread_cpu_seconds();
  for (long long k = 0; k < steps; ++k) {
    throw_if_interrupted();  // Ctrl-C ends the program between two steps (program/interrupt.hpp)
    if (!stepper->step(h, r.x, v)) {
      r.ok = false;
      r.message = format("step %lld failed: %s", k + 1, stepper->failure().reason.c_str());
      break;
    }
    if (!r.x.allFinite() || r.x.cwiseAbs().maxCoeff() > 100) {
      r.ok = false;
      r.message = format("diverged at step %lld", k + 1);
      break;
    }
  }
  r.seconds = thread_cpu_seconds() - t0;
  r.counters = stepper->counters();
  return r;
}

}  // namespace

Run run_to(const Scene& scene, const std::string& method, double T, long long steps, double repeat_below) {
  Run best = run_once(scene, method, T, steps);
  for (int k = 1; best.ok && k < 5 && best.seconds < repeat_below; ++k) {
    const Run again = run_once(scene, method, T, steps);
    best.seconds = std::min(best.seconds, again.seconds);
  }
  return best;
}

bool stays_bounded(const Scene& scene, const std::string& method, double h, int steps) {
  ForceField field(scene);
  auto stepper = ch10::make_method(method, field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] += 1e-6 * std::sin(1.7 * static_cast<double>(k));  // seed all modes
  for (int k = 0; k < steps; ++k) {
    throw_if_interrupted();
    stepper->step(h, x, v);
    if (!x.allFinite() || (x - scene.initial_positions()).cwiseAbs().maxCoeff() > 1.0) return false;
  }
  return true;
}

Vector reference(const Scene& scene, double T, long long steps, bool check, double& agreement) {
  ForceField field(scene);
  auto rk4 = make_stepper("rk4", field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  const double h = T / static_cast<double>(steps);
  for (long long k = 0; k < steps; ++k) {
    throw_if_interrupted();
    rk4->step(h, x, v);
  }
  agreement = -1;
  if (check) {
    auto rule38 = make_stepper("rule38", field);
    Vector y = scene.initial_positions(), w = scene.initial_velocities();
    for (long long k = 0; k < 2 * steps; ++k) rule38->step(h / 2, y, w);
    agreement = largest_distance(x, y);
  }
  return x;
}

void write_text(const std::string& dir, const std::string& name, const std::string& text) {
  OutputFile file(dir + "/" + name);
  std::fputs(text.c_str(), file.get());
  file.commit();
}

std::string step_text(double h) {
  const double per_second = 1 / h;
  if (std::abs(per_second - std::round(per_second)) < 1e-6 * per_second) return format("1/%.0f", per_second);
  return format("%.3g", h);
}

std::string stiffness_text(double K) {
  static const char* const superscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  const double e = std::round(std::log10(K));
  if (K > 0 && e >= 2 && e <= 9 && K == std::pow(10.0, e)) return std::string("10") + superscript[static_cast<int>(e)];
  return format("%g", K);
}

std::string format(const char* fmt, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}

}  // namespace ch10
