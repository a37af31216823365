// Chapter 6's comparison with Boost.Odeint, the runs and their timings (odeint_timings.hpp).
#include "odeint_timings.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "model/force_field.hpp"
#include "program/timing.hpp"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

namespace ch06 {

using namespace cloth;

namespace {

// odeint's runge_kutta4 driving the core's forces: the state is (x, v) of the free particles in one
// std::vector, the right-hand side (v, M^{-1} f(x, v)) from ForceField::acceleration.
Vector odeint_on_core_forces(ForceField& field, double h, double T) {
  const int n = field.dof_count();
  std::vector<double> y(2 * static_cast<std::size_t>(n));
  Eigen::Map<Vector>(y.data(), n) = field.scene().initial_positions();
  Eigen::Map<Vector>(y.data() + n, n) = field.scene().initial_velocities();
  const auto system = [&](const std::vector<double>& s, std::vector<double>& dsdt, double /*t*/) {
    const Eigen::Map<const Vector> x(s.data(), n), v(s.data() + n, n);
    Eigen::Map<Vector>(dsdt.data(), n) = v;
    Eigen::Map<Vector> a(dsdt.data() + n, n);
    field.acceleration(x, v, a);
  };
  boost::numeric::odeint::runge_kutta4<std::vector<double>> rk4;
  const long steps = std::lround(T / h);
  for (long k = 0; k < steps; ++k) rk4.do_step(std::cref(system), y, static_cast<double>(k) * h, h);
  return Eigen::Map<Vector>(y.data(), n);
}

// The core's generic Butcher-tableau engine with the rk4 tableau, the same steps, no driver and no outputs.
Vector core_engine(ForceField& field, double h, double T) {
  auto stepper = make_stepper("rk4", field);
  Vector x = field.scene().initial_positions(), v = field.scene().initial_velocities();
  const long steps = std::lround(T / h);
  for (long k = 0; k < steps; ++k) stepper->step(h, x, v);
  return x;
}

// One run in this process (program/timing.hpp: the thread's processor time beside the wall clock).
Seconds time_in_process(const std::function<void()>& body) {
  const Timing t = time_runs(body, {.runs = 1});
  return {t.fastest_wall, t.fastest_cpu};
}

}  // namespace

PlainFabric plain_fabric(const SceneParams& s) {
  return {s.grid.M, s.grid.N, s.grid.d, s.stiffness, s.damping, s.mass, s.gravity, s.initial_velocity_z};
}

// odeint takes the system by value: it is given by reference (std::cref), since a copy of the plain loop carries
// the springs and the Jacobian's pattern and odeint copies it at every step.
std::vector<double> plain_rk4(const PlainFabric& fabric, double h, double T) {
  std::vector<double> y = fabric.initial_state();
  boost::numeric::odeint::runge_kutta4<std::vector<double>> rk4;
  const long steps = std::lround(T / h);
  for (long n = 0; n < steps; ++n) rk4.do_step(std::cref(fabric), y, static_cast<double>(n) * h, h);
  return y;
}

double lowest_z(const double* x, long size) {
  double z = INFINITY;
  for (long k = 2; k < size; k += 3) z = std::min(z, x[k]);
  return z;
}

std::vector<std::string> scene_arguments(const SceneParams& s, double h, double T) {
  return {"--grid", std::to_string(s.grid.M) + "x" + std::to_string(s.grid.N), "--spacing", format_number(s.grid.d),
          "--mass", format_number(s.mass), "--v0", format_number(s.initial_velocity_z), "--K",
          format_number(s.stiffness), "--damping", format_number(s.damping), "--dt", format_number(h), "--t-end",
          format_number(T)};
}

Programs time_programs(const std::string& self, const std::string& ch03, int runs,
                       const std::vector<std::string>& scene_args, const std::string& scratch) {
  std::vector<std::string> plain_args = {self, "--program", "plain"}, ch03_args = {ch03};
  plain_args.insert(plain_args.end(), scene_args.begin(), scene_args.end());
  ch03_args.insert(ch03_args.end(), scene_args.begin(), scene_args.end());
  ch03_args.insert(ch03_args.end(), {"--out", scratch + "/ch03_run"});
  Programs out;
  for (int k = 0; k < runs; ++k) out.plain.add(time_process(plain_args)), out.ch03.add(time_process(ch03_args));
  return out;
}

Integrators time_integrators(const SceneParams& s, double h, double T, int runs) {
  const Scene scene(s);
  ForceField field(scene);
  Vector x_odeint, x_core;
  std::vector<double> y_plain;
  const PlainFabric plain = plain_fabric(s);
  Integrators out;
  for (int k = 0; k < runs; ++k) {  // alternated, so that a busy spell of the machine hits both
    out.odeint.add(time_in_process([&] { x_odeint = odeint_on_core_forces(field, h, T); }));
    out.engine.add(time_in_process([&] { x_core = core_engine(field, h, T); }));
  }
  out.plain = best_of(runs, [&] { return time_in_process([&] { y_plain = plain_rk4(plain, h, T); }); });
  out.z_odeint = lowest_z(x_odeint.data(), x_odeint.size()), out.z_engine = lowest_z(x_core.data(), x_core.size());
  out.z_plain = lowest_z(y_plain.data(), 3 * plain.particles());
  return out;
}

MarkdownTable one_step_table(const std::string& bin, const std::vector<std::string>& scene_args,
                             const std::string& scratch, int runs) {
  MarkdownTable one_step({"one step of h = 0.01 s, whole process", "wall [ms]", "CPU [ms]"}, "lrr");
  for (const char* program : {"ch02_explicit_euler", "ch03_runge_kutta", "ch04_implicit_euler"}) {
    std::vector<std::string> args = {(std::filesystem::path(bin) / program).string()};
    args.insert(args.end(), scene_args.begin(), scene_args.end() - 4);  // the scene, without --dt and --t-end
    args.insert(args.end(), {"--dt", "0.01", "--t-end", "0.01", "--out", scratch + "/one_step_" + program});
    const Seconds t = best_of(runs, [&] { return time_process(args); }).best;
    one_step.add_row({std::string("`") + program + "`", format_fixed(1e3 * t.wall, 1), format_fixed(1e3 * t.cpu, 1)});
  }
  return one_step;
}

}  // namespace ch06
