// Chapter 10's measuring tools: the chapter's methods by their one name, a run to T with the error at T against a
// reference (timed by program/timing.hpp), and the fabric scenes of the chapter (the same square metre at any
// resolution and stiffness).
#pragma once

#include "integrators/stepper.hpp"
#include "model/scene.hpp"
#include "program/output.hpp"

#include <memory>
#include <string>
#include <vector>

namespace ch10 {

/// The chapter's fabric: a square of side 0.95 m with n particles per side, areal density 0.25 kg/m^2 (so
/// m = 6.25e-4 kg at n = 20), one stiffness K for every family, D = 0.01, corners pinned, released from rest.
cloth::SceneParams fabric(int n, double K);

/// A method by its one composed name (integrators/configuration.hpp: "rk4", "implicit_euler/one/cg",
/// "xpbd/16sub"), with the chapter's Newton settings (tolerance 1e-6, at most 100 iterations, CG to 1e-8) and the
/// book's default rule for the Newton matrix. Built by cloth::make_stepper.
std::unique_ptr<cloth::Stepper> make_method(const std::string& name, cloth::ForceField& field);
/// Whether the name's registry method is explicit (an explicit, embedded or partitioned Runge-Kutta method).
bool is_explicit(const std::string& name);
/// Its one name as every table prints it (configuration_name: "local_global/10it" is "local_global").
std::string label(const std::string& name);

/// The final positions of a run of `steps` equal steps to T, or ok = false with where it stopped.
struct Run {
  cloth::Vector x;
  bool ok = true;
  std::string message;
  double seconds = 0;  ///< thread CPU seconds of the (best) run
  cloth::StepCounters counters;
};
/// Runs `method` on `scene` to T; when the run is shorter than `repeat_below` seconds it is repeated (up to 5
/// runs in all) and the fastest time is kept: on a busy machine the minimum is the least disturbed.
Run run_to(const cloth::Scene& scene, const std::string& method, double T, long long steps,
           double repeat_below = 0.2);

/// Whether `method` at step h keeps the scene's rest state, seeded with 1e-6 m in every coordinate, within 1 m
/// of rest for `steps` steps (the stable-step bisection of Chapter 10).
bool stays_bounded(const cloth::Scene& scene, const std::string& method, double h, int steps);

/// A reference for T: RK4 with `steps` steps; when `check` it is compared with the 3/8 rule at twice as many
/// steps and `agreement` is their largest difference (else -1).
cloth::Vector reference(const cloth::Scene& scene, double T, long long steps, bool check, double& agreement);

/// Writes `text` to DIR/name through cloth::OutputFile (whole or not at all).
void write_text(const std::string& dir, const std::string& name, const std::string& text);

/// A step as the page writes it: "1/60" when 1/h is whole, else "4.7e-05".
std::string step_text(double h);

/// A stiffness as the page writes it: a power of ten from 100 on as 10² ... 10⁶ (the page's 10^6: a table cannot
/// hold a formula), any other value as printf's %g.
std::string stiffness_text(double K);

/// printf into a std::string.
std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace ch10
