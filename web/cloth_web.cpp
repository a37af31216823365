// The book's core in the browser: one run of `ch10_cloth` (any method of the registry on any scene of the common
// flags), compiled to WebAssembly and driven a few steps at a time by the pages' demos (web/viewer.js). The flags
// are parsed by the programs' own CommandLine, the method made by the registry, the step loop is the driver's
// (integrators/simulate.cpp) and the final state is written by the programs' write_final, so the browser and the
// native program compute, refuse and print the same things.
#include "analysis/fastest_modes.hpp"
#include "analysis/stability_function.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/command_line.hpp"
#include "program/method_flags.hpp"

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace cloth {

namespace {

constexpr const char* program = "ch10_cloth";  // the native program whose flags, messages and outputs these are

}  // namespace

/// One run, stepped on demand. Built from the command line `ch10_cloth` would take, one argument a line; an input
/// the program would refuse leaves the run invalid, with the program's one-line message in error().
class BrowserRun {
 public:
  explicit BrowserRun(const std::string& arguments) {
    try {
      start(arguments);
    } catch (const InputError& e) {
      error_ = std::string(program) + ": " + e.what();
    } catch (const std::exception& e) {
      error_ = std::string(program) + ": internal error: " + e.what();
    }
  }

  [[nodiscard]] bool valid() const { return error_.empty(); }
  [[nodiscard]] const std::string& error() const { return error_; }

  /// Takes up to `count` more steps of the run, exactly as simulate() takes them (the same step sizes, the last
  /// one shortened to reach T, the same divergence test, the last sane state kept); returns the steps taken.
  int advance(int count) {
    int taken = 0;
    while (taken < count && running()) {
      // [browser_step]
      const long long k = result_.steps;
      const double t0 = static_cast<double>(k) * h_;
      const double t1 = k + 1 == total_steps_ ? T_ : static_cast<double>(k + 1) * h_;
      const double step_h = k + 1 == total_steps_ && std::abs(T_ - t0 - h_) > 1e-9 * h_ ? T_ - t0 : h_;
      x_prev_ = result_.x;
      v_prev_ = result_.v;
      if (!stepper_->step(step_h, result_.x, result_.v)) {
        stop_run(result_, RunStatus::step_failed, stepper_->failure().kind, k + 1, t1, stepper_->failure().reason);
        break;
      }
      if (std::string why = divergence_reason(result_.x, result_.v, radius_); !why.empty()) {
        stop_run(result_, RunStatus::diverged, StepFailureKind::none, k + 1, t1, std::move(why));
        result_.x = x_prev_;
        result_.v = v_prev_;
        break;
      }
      result_.steps = k + 1;
      result_.t = t1;
      // [browser_step]
      ++taken;
    }
    if (!running() && result_.status == RunStatus::ok) result_.message = "ok";
    return taken;
  }

  /// Wall-clock seconds per step of the whole run timed as the native program times it: simulate() from the
  /// scene's initial state, energy and frames recorded, RunResult::wall_seconds over its steps (run.txt's
  /// wall_seconds / steps). The run being stepped is left as it was.
  double seconds_per_step() {
    const RunResult timed = simulate(*stepper_, settings_);
    return timed.steps > 0 ? timed.wall_seconds / static_cast<double>(timed.steps) : 0.0;
  }

  [[nodiscard]] bool running() const { return result_.status == RunStatus::ok && result_.steps < total_steps_; }
  /// "running", or run.txt's status: "ok", "diverged", "step_failed".
  [[nodiscard]] std::string status() const { return running() ? "running" : run_status_name(result_.status); }
  /// The line the native program prints when its run stops early (report_stop's), or "" while it has not.
  [[nodiscard]] std::string stop_message() const {
    if (result_.status == RunStatus::ok) return "";
    return std::string(program) + ": " + stepper_->name() + " " + result_.message;
  }
  [[nodiscard]] double time() const { return result_.t; }
  [[nodiscard]] double steps() const { return static_cast<double>(result_.steps); }
  [[nodiscard]] double total_steps() const { return static_cast<double>(total_steps_); }
  [[nodiscard]] double dt() const { return h_; }
  [[nodiscard]] int rows() const { return scene_->grid().M; }
  [[nodiscard]] int columns() const { return scene_->grid().N; }
  [[nodiscard]] std::string method() const { return stepper_->name(); }

  /// Every particle's position in grid order (pinned ones at rest), 3 per particle: a view into the module's
  /// memory, valid until the next call.
  emscripten::val positions() {
    scene_->all_positions(result_.x, all_);
    return emscripten::val(emscripten::typed_memory_view(all_.size(), all_.data()));
  }
  /// Every particle's velocity in grid order (pinned ones 0), as positions().
  emscripten::val velocities() {
    all_.setZero();
    for (int s = 0; s < scene_->free_count(); ++s)
      all_.segment<3>(3 * scene_->particle_of_slot(s)) = result_.v.segment<3>(3 * s);
    return emscripten::val(emscripten::typed_memory_view(all_.size(), all_.data()));
  }
  /// Kinetic, gravitational and spring energy, and their sum [J], as energy.dat's columns.
  emscripten::val energy() {
    const Energy e = field_->energy(result_.x, result_.v);
    energy_ = {e.kinetic, e.gravity, e.spring, e.total()};
    return emscripten::val(emscripten::typed_memory_view(energy_.size(), energy_.data()));
  }

  /// The state as final.dat holds it (program/output.cpp's write_final): `# i j x y z vx vy vz`, one particle a
  /// line in grid order, pinned ones at rest, each number with 17 significant digits. write_final prints them
  /// with std::to_chars, which the C++ standard defines as printf's %.17g, format_number's rule: Emscripten 3.1's
  /// libc++ has no floating-point to_chars, so the module formats with format_number.
  [[nodiscard]] std::string final_state() const {
    const Grid& g = scene_->grid();
    std::string text = "# i j x y z vx vy vz\n";
    for (int i = 0; i < g.M; ++i)
      for (int j = 0; j < g.N; ++j) {
        const int s = scene_->slot(g.particle(i, j));
        Eigen::Vector3d p = scene_->rest_positions().segment<3>(3 * s), u = Eigen::Vector3d::Zero();
        if (s < scene_->free_count()) p = result_.x.segment<3>(3 * s), u = result_.v.segment<3>(3 * s);
        text += std::to_string(i) + " " + std::to_string(j);
        for (const double value : {p[0], p[1], p[2], u[0], u[1], u[2]}) text += " " + format_number(value, 17);
        text += "\n";
      }
    return text;
  }

  /// The largest step h for which the run's explicit Runge-Kutta method is stable on the cloth's fastest mode at
  /// rest: omega_max from the stiffness Jacobian, c_max from the damping Jacobian (the same mode when every
  /// spring has the same K and D, the damping then proportional), the mode's eigenvalues the roots of
  /// lambda^2 + c lambda + omega^2 = 0, and h the edge of |R(h lambda)| <= 1 along them (Chapter 7). 0 for a
  /// method without a tableau's stability function.
  double predicted_h_max() {
    const Method& m = find_method(stepper_->name());
    if (!m.tableau || m.family != MethodFamily::explicit_runge_kutta) return 0;
    const double omega = fastest_rest_frequency(*field_);
    const Vector x = scene_->initial_positions();
    const double c = fastest_damping_rate(*field_, x, Vector::Zero(x.size()));
    const std::complex<double> root = std::sqrt(std::complex<double>(c * c / 4 - omega * omega));
    const std::complex<double> lambda[2] = {-c / 2 + root, -c / 2 - root};
    const ButcherTableau& tableau = *m.tableau;
    const auto stable = [&](double h) {
      return std::abs(stability_function(tableau, h * lambda[0])) <= 1 &&
             std::abs(stability_function(tableau, h * lambda[1])) <= 1;
    };
    return stability_limit_along(stable, 10.0 / std::abs(lambda[0]));
  }

 private:
  void start(const std::string& arguments) {
    std::vector<std::string> args{program};
    std::istringstream lines(arguments);
    for (std::string line; std::getline(lines, line);)
      if (!line.empty()) args.push_back(line);
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());

    // ch10_cloth's command line: the common flags, --method, Newton's flags and the iterative methods' flags.
    std::string method_name = "implicit_euler";
    NewtonFlags newton;
    IterationFlags iterations;
    CommandLine cli(program, "one run of the cloth with any method of the registry");
    cli.add_value("--method", "NAME", "a method of the registry", [&](const std::string& s) { method_name = s; });
    newton.add_to(cli);
    iterations.add_to(cli);
    const Options opt = cli.parse(static_cast<int>(argv.size()), argv.data());
    const Method* method = nullptr;
    try {
      method = &find_method(method_name);
    } catch (const InputError& e) {
      throw InputError(std::string("--method: ") + e.what());
    }
    scene_ = std::make_unique<Scene>(opt.scene);
    field_ = std::make_unique<ForceField>(*scene_);
    const MethodSettings settings = method_settings(*method, *scene_, newton, iterations);
    try {
      stepper_ = method->stepper(*field_, settings);
    } catch (const InputError& e) {
      throw InputError("--method " + method->name + ": " + e.what());
    }
    settings_ = opt.run;
    settings_.stop = nullptr;  // no signals in a browser
    h_ = opt.run.dt;
    T_ = opt.run.t_end;
    total_steps_ = step_count(opt.run);
    radius_ = divergence_radius(*scene_, T_);
    result_.x = scene_->initial_positions();
    result_.v = scene_->initial_velocities();
    x_prev_ = result_.x;
    v_prev_ = result_.v;
    all_ = Vector::Zero(3 * scene_->particle_count());
  }

  std::string error_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<ForceField> field_;
  std::unique_ptr<Stepper> stepper_;
  RunSettings settings_;
  double h_ = 0, T_ = 0, radius_ = 0;
  long long total_steps_ = 0;
  RunResult result_;  // status, message, steps, t and the state (x, v), as simulate() keeps them
  Vector x_prev_, v_prev_, all_;
  std::array<double, 4> energy_{};
};

/// Every method of the registry: name, title and family, one method a line, tab-separated.
std::string registry_methods() {
  std::string text;
  for (const Method& m : methods()) text += m.name + "\t" + m.title + "\t" + method_families().name(m.family) + "\n";
  return text;
}

}  // namespace cloth

EMSCRIPTEN_BINDINGS(cloth_web) {
  using cloth::BrowserRun;
  emscripten::class_<BrowserRun>("Run")
      .constructor<std::string>()
      .function("valid", &BrowserRun::valid)
      .function("error", &BrowserRun::error)
      .function("advance", &BrowserRun::advance)
      .function("secondsPerStep", &BrowserRun::seconds_per_step)
      .function("running", &BrowserRun::running)
      .function("status", &BrowserRun::status)
      .function("stopMessage", &BrowserRun::stop_message)
      .function("time", &BrowserRun::time)
      .function("steps", &BrowserRun::steps)
      .function("totalSteps", &BrowserRun::total_steps)
      .function("dt", &BrowserRun::dt)
      .function("rows", &BrowserRun::rows)
      .function("columns", &BrowserRun::columns)
      .function("method", &BrowserRun::method)
      .function("positions", &BrowserRun::positions)
      .function("velocities", &BrowserRun::velocities)
      .function("energy", &BrowserRun::energy)
      .function("finalState", &BrowserRun::final_state)
      .function("predictedHMax", &BrowserRun::predicted_h_max);
  emscripten::function("methods", &cloth::registry_methods);
}
