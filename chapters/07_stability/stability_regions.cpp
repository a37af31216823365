// Stability models, growth factors and the stability regions of Chapter 7.
#include "stability_regions.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/method_registry.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ch07 {

std::string wrapped(const std::string& line, std::size_t width) {
  std::string out, current;
  std::size_t start = 0;
  while (start <= line.size()) {
    std::size_t end = line.find(' ', start);
    if (end == std::string::npos) end = line.size();
    const std::string word = line.substr(start, end - start);
    if (!current.empty() && current.size() + 1 + word.size() > width) {
      out += current + "\n";
      current = "    " + word;
    } else {
      current += (current.empty() ? "" : " ") + word;
    }
    start = end + 1;
  }
  return out + current + "\n";
}

std::string method_label(const std::string& method) {
  if (method == "explicit_euler") return "explicit Euler";
  if (method == "symplectic_euler") return "symplectic Euler";
  if (method == "implicit_euler") return "implicit Euler";
  if (method == "heun") return "Heun";
  if (method == "rk4") return "RK4";
  return method;
}

StabilityModel stability_model(const std::string& method) {
  const cloth::Method& row = cloth::find_method(method);
  StabilityModel model{method, StabilityModel::Kind::polynomial, {}, nullptr};
  if (row.family == cloth::MethodFamily::explicit_runge_kutta) {
    model.polynomial = cloth::stability_polynomial(*row.tableau);  // R(z) from A and b, never typed in
  } else if (row.name == "symplectic_euler") {
    model.kind = StabilityModel::Kind::symplectic_euler;
  } else if (row.family == cloth::MethodFamily::implicit_runge_kutta && row.tableau && row.name != "implicit_euler") {
    model.kind = StabilityModel::Kind::tableau;  // Chapter 9's DIRKs: R(z) from A and b as well
    model.tableau = &*row.tableau;
  } else if (row.stability != nullptr) {
    model.kind = StabilityModel::Kind::closed_form;
    model.stability = row.stability;
  } else {
    throw cloth::InputError("method '" + method + "' has no stability model in this chapter");
  }
  return model;
}

// [growth_factor]
// The largest factor by which one step of the method multiplies a mode of the linearised cloth: |R(h lambda)|
// for a Runge-Kutta method, |1/(1 - h lambda)| for implicit Euler, the spectral radius of the 2 x 2 step matrix
// for symplectic Euler. The step is linearly stable when this is at most 1.
double growth_factor(const StabilityModel& model, double h, const std::vector<Mode>& modes) {
  double worst = 0;
  for (const Mode& mode : modes) {
    switch (model.kind) {
      case StabilityModel::Kind::symplectic_euler:
        worst = std::max(worst, cloth::symplectic_euler_amplification(h * mode[0], h * mode[1]));
        break;
      case StabilityModel::Kind::tableau:
        for (const Complex& lambda : mode)
          worst = std::max(worst, std::abs(cloth::stability_function(*model.tableau, h * lambda)));
        break;
      case StabilityModel::Kind::closed_form:
        for (const Complex& lambda : mode) worst = std::max(worst, std::abs(model.stability(h * lambda)));
        break;
      case StabilityModel::Kind::polynomial:
        for (const Complex& lambda : mode) {
          const Complex z = h * lambda;
          Complex R = 0;
          for (auto r = model.polynomial.rbegin(); r != model.polynomial.rend(); ++r) R = R * z + *r;  // Horner
          worst = std::max(worst, std::abs(R));
        }
        break;
    }
  }
  return worst;
}
// [growth_factor]

std::vector<std::string> region_methods() {
  std::vector<std::string> methods;
  for (const cloth::Method* m : cloth::methods_of(cloth::MethodFamily::explicit_runge_kutta)) methods.push_back(m->name);
  methods.emplace_back("implicit_euler");
  methods.emplace_back("symplectic_euler");
  for (const cloth::Method* m : cloth::methods_of(cloth::MethodFamily::implicit_runge_kutta))
    if (m->tableau && m->name != "implicit_euler") methods.push_back(m->name);
  return methods;
}

std::vector<std::pair<std::string, std::string>> stability_regions(const std::string& dir) {
  // |R(z)| on a grid of the z-plane; the figure draws the contour |R| = 1. Symplectic Euler's is drawn for
  // conjugate-pair modes (z, conj z). growth_factor takes the larger of |R(z)|, |R(conj z)|: equal for real
  // tableaus.
  cloth::OutputFile regions(dir + "/regions.dat");
  for (const std::string& method : region_methods()) {
    const StabilityModel model = stability_model(method);
    // The implicit methods' regions are unbounded: their edges, where there are any, lie in the right half-plane.
    const bool wide = model.kind == StabilityModel::Kind::tableau;
    std::fprintf(regions.get(), "# %s: Re z, Im z, |R(z)|\n", method.c_str());
    for (int i = 0; i <= 260; ++i) {
      const double re = wide ? -4.0 + 14.0 * i / 260 : -4.0 + 6.5 * i / 260;
      for (int j = 0; j <= 240; ++j) {
        const double im = wide ? -7.0 + 14.0 * j / 240 : -3.5 + 7.0 * j / 240;
        const Complex z(re, im);
        std::fprintf(regions.get(), "%.6g %.6g %.6g\n", re, im, std::min(growth_factor(model, 1.0, {Mode{z, std::conj(z)}}), 10.0));
      }
      std::fprintf(regions.get(), "\n");
    }
    std::fprintf(regions.get(), "\n");
  }
  regions.commit();

  // Each region's reach along the two axes, printed and checked against the closed forms in the text.
  std::printf("stability interval of each method along the negative real axis and the imaginary axis:\n");
  std::vector<std::pair<std::string, std::string>> summary;
  for (const std::string& method : region_methods()) {
    const StabilityModel model = stability_model(method);
    if (method == "implicit_euler" || model.kind == StabilityModel::Kind::tableau) continue;  // A-stable
    const auto stable_at = [&](Complex z) { return growth_factor(model, 1.0, {Mode{z, std::conj(z)}}) <= 1 + 1e-12; };
    const double real = cloth::stability_limit_along([&](double t) { return stable_at({-t, 0}); }, 10);
    const double imag = cloth::stability_limit_along([&](double t) { return stable_at({-1e-300, t}); }, 10);
    std::printf("  %-17s real %.4f  imaginary %.4f\n", method.c_str(), real, imag);
    summary.emplace_back(method + "_real_limit", cloth::format_number(real));
    summary.emplace_back(method + "_imaginary_limit", cloth::format_number(imag));
  }
  return summary;
}

}  // namespace ch07
