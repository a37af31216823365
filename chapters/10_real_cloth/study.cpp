// Chapter 10's measuring tools (see study.hpp).
#include "study.hpp"

#include "integrators/method_registry.hpp"
#include "model/fabric.hpp"
#include "program/interrupt.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <ctime>
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

// A method of the chapter, parsed from its key: a registry name as it stands ("symplectic_euler", "rk4"),
// "ie_<newton|1newton>_<direct|cg>" for the registry's implicit Euler with full Newton or one iteration, on the
// direct or the CG path, "local_global_<iterations>", "xpbd_<iterations>_<substeps>" (iterations per substep,
// substeps per step) or "small_steps_<substeps>".
struct Configuration {
  std::string method;  ///< the registry's name
  MethodSettings settings;
  std::string detail;  ///< what the settings add to the registry's title
};

Configuration configuration(const std::string& key) {
  Configuration c{key, {}, ""};
  if (key.rfind("ie_", 0) == 0) {
    c.method = "implicit_euler";
    // Full Newton: the exact Jacobian (block LDU for the damped cloth), or the definite one with CG. From the flat
    // sheet at rest a frame-sized step takes Newton through compressed, indefinite states, where its line search
    // on the incremental potential may backtrack (Chapter 4); the cap of 100 is a safeguard. Its tolerance, 1e-6
    // relative in the velocity, is a position error below 1e-6 h, far under every error this chapter measures.
    NewtonSettings& newton = c.settings.newton;
    newton.max_iterations = 100;
    newton.tolerance = 1e-6;
    const std::string rest = key.substr(3);
    if (rest == "newton_direct" || rest == "1newton_direct") {
      c.detail = ", direct";
    } else if (rest == "newton_cg" || rest == "1newton_cg") {
      newton.treatment = StiffnessTreatment::definite;
      newton.solver = LinearSolverKind::cg;
      newton.cg_tolerance = 1e-8;
      c.detail = ", CG";
    } else {
      throw std::logic_error("ch10: unknown method " + key);
    }
    const bool one = rest.rfind("1newton", 0) == 0;
    if (one) newton.variant = NewtonVariant::one;  // Baraff and Witkin's single linearised step
    c.detail = (one ? ", 1 iteration" : ", Newton") + c.detail;
  } else if (key.rfind("local_global_", 0) == 0) {
    c.method = "local_global";
    c.settings.local_global_iterations = std::stoi(key.substr(13));
    c.detail = ", " + key.substr(13) + " iterations";
  } else if (key.rfind("xpbd_", 0) == 0) {
    c.method = "xpbd";
    const std::size_t split = key.find('_', 5);
    if (split == std::string::npos) throw std::logic_error("ch10: unknown method " + key);
    c.settings.xpbd_iterations = std::stoi(key.substr(5, split - 5));
    c.settings.substeps = std::stoi(key.substr(split + 1));
    c.detail = ", " + key.substr(5, split - 5) + " iterations, " + key.substr(split + 1) + " substeps";
  } else if (key.rfind("small_steps_", 0) == 0) {
    c.method = "small_steps";
    c.settings.substeps = std::stoi(key.substr(12));
    c.detail = ", " + key.substr(12) + " substeps";
  }
  find_method(c.method);  // throws for a name the registry does not know
  return c;
}

}  // namespace

std::unique_ptr<Stepper> make_method(const std::string& key, ForceField& field) {
  const Configuration c = configuration(key);
  return make_stepper(c.method, field, c.settings);
}

bool is_explicit(const std::string& key) {
  const MethodFamily family = find_method(configuration(key).method).family;
  return family == MethodFamily::explicit_runge_kutta || family == MethodFamily::partitioned ||
         family == MethodFamily::embedded_runge_kutta;
}

std::string label(const std::string& key) {
  const Configuration c = configuration(key);
  return find_method(c.method).title + c.detail;
}

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

namespace {

Run run_once(const Scene& scene, const std::string& method, double T, long long steps) {
  ForceField field(scene);
  auto stepper = make_method(method, field);
  Run r;
  r.x = scene.initial_positions();
  Vector v = scene.initial_velocities();
  const double h = T / static_cast<double>(steps);
  const double t0 = cpu_seconds();
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
  r.seconds = cpu_seconds() - t0;
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

double max_distance(const Vector& a, const Vector& b) {
  double worst = 0;
  for (Eigen::Index k = 0; k + 2 < a.size(); k += 3) worst = std::max(worst, (a.segment<3>(k) - b.segment<3>(k)).norm());
  return worst;
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
    agreement = max_distance(x, y);
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

std::string format(const char* fmt, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buffer, sizeof buffer, fmt, args);
  va_end(args);
  return buffer;
}

}  // namespace ch10
