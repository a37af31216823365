// Chapter 10's rotation study: two particles hung from a pinned edge by stiff springs and turned rigidly about it,
// stepped by implicit Euler; the angular rate after each step against the stiff-limit prediction the page derives
// (a rigid rotation loses energy at the rate 2 h w0^2 at first), with RK4 at a small step as the exact motion.
#include "curtain_runs.hpp"

#include "model/single_spring.hpp"

#include <cmath>

using namespace cloth;

namespace ch10 {

namespace {

// [rotation]
/// Two particles hanging from a pinned edge by stiff springs (single_spring_params: no gravity, no damping), turned
/// rigidly about the edge at w0 rad/s: the exact motion turns forever at w0. Implicit Euler's angular rate after
/// each step, against the stiff-limit prediction the page derives: the k-th step turns the spring by the angle
/// a_1 = atan(h w0), a_{k+1} = atan(sin a_k / (2 - cos a_k)), and leaves it turning at w_k = sin(a_k) / h.
struct RotationRun {
  std::string method;
  double h;
  std::vector<double> t, w;  // the measured angular rate
};

RotationRun rotation(const std::string& method, double h, double Kspring, double w0, double T) {
  SceneParams p = single_spring_params(Kspring, 0);
  p.initial_velocity_z = 0;
  p.initial_swing = w0;
  const Scene scene(p);
  ForceField field(scene);
  auto stepper = make_method(method, field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  const double axis_y = (p.grid.N - 1) * p.grid.d;
  const auto rate = [&] {  // about the edge's line: (r x v)_x / |r|^2 of the first free particle
    const double dy = x[1] - axis_y, dz = x[2];
    return -(dy * v[2] - dz * v[1]) / (dy * dy + dz * dz);
  };
  RotationRun r{method, h, {0}, {rate()}};
  for (long long k = 1; k <= std::llround(T / h); ++k) {
    if (!stepper->step(h, x, v)) break;
    r.t.push_back(static_cast<double>(k) * h);
    r.w.push_back(rate());
  }
  return r;
}
// [rotation]

}  // namespace

void rotation_study(const std::string& out, const std::string& command) {
  const double Kspring = 1e6, w0 = 10, T = 1;  // spring frequency 1000 rad/s: h sqrt(K/m) >= 8 at these steps
  MarkdownTable t({"h [s]", "h w0", "predicted w(T) / w0", "implicit Euler, Newton", "implicit Euler, 1 iteration",
                   "RK4 (at 1e-4 s)"},
                  "rrrrrr");
  std::string dat = "# t w_measured w_predicted; one block per (method, h): implicit_euler/exact then "
                    "implicit_euler/one/exact at h = 1/30, 1/60, 1/120, then rk4 at 1e-4\n";
  const RotationRun exact = rotation("rk4", 1e-4, Kspring, w0, T);
  // The stiff-limit recurrence of the page: the rate after each step of h.
  const auto predicted_rates = [&](double h) {
    std::vector<double> w = {w0};
    double a = std::atan(h * w0);
    for (long long k = 1; k <= std::llround(T / h); ++k, a = std::atan(std::sin(a) / (2 - std::cos(a))))
      w.push_back(std::sin(a) / h);
    return w;
  };
  for (double h : frame_steps) {
    const std::vector<double> prediction = predicted_rates(h);
    const double predicted = prediction.back();
    std::vector<std::string> row = {step_text(h), format("%.3g", h * w0), format("%.3f", predicted / w0)};
    for (const char* method : {"implicit_euler/exact", "implicit_euler/one/exact"}) {
      const RotationRun r = rotation(method, h, Kspring, w0, T);
      row.push_back(format("%.3f", r.w.back() / w0));
      dat += format("# %s h = %s\n", method, step_text(h).c_str());
      for (std::size_t k = 0; k < r.t.size(); ++k) dat += format("%.6f %.6e %.6e\n", r.t[k], r.w[k], prediction[k]);
      dat += "\n\n";
    }
    row.push_back(format("%.4f", exact.w.back() / w0));
    t.add_row(row);
  }
  dat += "# rk4 h = 1e-4\n";
  for (std::size_t k = 0; k < exact.t.size(); k += 100) dat += format("%.6f %.6e %.6e\n", exact.t[k], exact.w[k], w0);
  write_table_fragment(out + "/rotation.md", t, command);
  write_text(out, "rotation.dat", dat);
}

}  // namespace ch10
