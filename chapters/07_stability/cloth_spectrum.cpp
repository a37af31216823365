// Rest and sagged spectra of the cloth for Chapter 7.
#include "cloth_spectrum.hpp"

#include "parallel_for.hpp"

#include "base/format_number.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ch07 {

using cloth::ForceField;
using cloth::Scene;
using cloth::SceneParams;
using cloth::Vector;

SceneParams with_stiffness(SceneParams scene, double K, double D) {
  scene.stiffness = K;
  scene.damping = D;
  return scene;
}

RestSpectrum rest_spectrum(const SceneParams& scene) {
  // L is -M^{-1} df/dx of the flat sheet with K = 1, times m.
  const SceneParams unit = with_stiffness(scene, 1.0, 0.0);
  const Scene unit_scene(unit);
  ForceField field(unit_scene);
  RestSpectrum rest;
  if (unit_scene.dof_count() <= cloth::dense_symmetric_limit) {
    rest.mu = cloth::stiffness_eigenvalues(field, unit_scene.initial_positions());
    for (double& u : rest.mu) u = std::max(u, 0.0) * unit.mass;  // rounding below 0 is 0
    rest.mu_max = rest.mu.back();
    rest.zero_count = static_cast<int>(
        std::count_if(rest.mu.begin(), rest.mu.end(), [&](double u) { return u < 1e-9 * rest.mu_max; }));
    return rest;
  }
  rest.exact = false;
  rest.mu_max = cloth::largest_stiffness_eigenvalues(field, unit_scene.initial_positions(), 1).at(0) * unit.mass;
  const int samples = 2000;
  for (int k = 0; k <= samples; ++k) rest.mu.push_back(rest.mu_max * k / samples);
  return rest;
}

std::vector<Mode> rest_modes(const RestSpectrum& rest, double K, double D, double m) {
  std::vector<Mode> modes;
  modes.reserve(rest.mu.size());
  for (double u : rest.mu) modes.push_back(cloth::mode_eigenvalues(K * u / m, D * u / m));
  return modes;
}

const cloth::Equilibrium& Equilibria::at(double K) {
  const auto found = by_stiffness_.find(K);
  if (found != by_stiffness_.end()) return found->second;
  const Scene scene(with_stiffness(scene_, K, 0.0));
  ForceField field(scene);
  cloth::Equilibrium eq = cloth::static_equilibrium(field);
  if (!eq.converged)
    std::fprintf(stderr, "ch07_stability: the sagged equilibrium for K = %g did not converge (|f| = %.3g N)\n", K,
                 eq.residual);
  return by_stiffness_.emplace(K, std::move(eq)).first->second;
}

std::vector<Complex> largest_eigenvalues(ForceField& field, const Vector& x, double D, int count) {
  if (D != 0) return cloth::largest_eigenvalues(field, x, Vector::Zero(x.size()), count);
  std::vector<Complex> lambda;
  for (double w2 : cloth::largest_stiffness_eigenvalues(field, x, (count + 1) / 2))
    for (const Complex& l : cloth::mode_eigenvalues(w2, 0)) lambda.push_back(l);
  return lambda;
}

void Equilibria::prepare(const std::vector<double>& stiffnesses, int threads) {
  std::vector<double> missing;
  for (double K : stiffnesses)
    if (by_stiffness_.count(K) == 0 && std::find(missing.begin(), missing.end(), K) == missing.end()) missing.push_back(K);
  std::vector<cloth::Equilibrium> found(missing.size());
  parallel_for(missing.size(), threads, [&](std::size_t k) {
    const Scene scene(with_stiffness(scene_, missing[k], 0.0));
    ForceField field(scene);
    found[k] = cloth::static_equilibrium(field);
  });
  for (std::size_t k = 0; k < missing.size(); ++k) {
    if (!found[k].converged)
      std::fprintf(stderr, "ch07_stability: the sagged equilibrium for K = %g did not converge (|f| = %.3g N)\n",
                   missing[k], found[k].residual);
    by_stiffness_.emplace(missing[k], std::move(found[k]));
  }
}

std::vector<Mode> modes_of(const std::vector<Complex>& lambda, bool pairs_only) {
  std::vector<Mode> modes;
  const auto is_pair = [](const Complex& l) { return std::abs(l.imag()) > 1e-9 * std::abs(l); };
  if (pairs_only && (lambda.empty() || !is_pair(lambda.front()))) return modes;
  for (const Complex& l : lambda) {
    if (is_pair(l) && l.imag() > 0) modes.push_back({l, std::conj(l)});
    if (!is_pair(l) && !pairs_only) modes.push_back({l, l});
  }
  return modes;
}

namespace {

// How many of the largest eigenvalues stand for the whole spectrum where it is too large to compute.
constexpr int extreme_count = 12;

struct SaggedSpectrum {
  std::vector<Complex> lambda;
  std::string how;
};

SaggedSpectrum sagged_spectrum(ForceField& field, const Vector& x, double D, bool dense_damped) {
  const int n = field.dof_count();
  const Vector zero = Vector::Zero(n);
  SaggedSpectrum s;
  if (D == 0) {
    // Undamped: lambda = +-i omega, omega^2 the eigenvalues of -M^{-1} df/dx (symmetric).
    const bool dense = n <= cloth::dense_symmetric_limit;
    const std::vector<double> omega2 =
        dense ? cloth::stiffness_eigenvalues(field, x) : cloth::largest_stiffness_eigenvalues(field, x, extreme_count);
    for (double w2 : omega2)
      for (const Complex& l : cloth::mode_eigenvalues(w2, 0)) s.lambda.push_back(l);
    s.how = dense ? "all, symmetric solver" : "largest, Lanczos";
    return s;
  }
  if (dense_damped && n <= cloth::dense_general_limit) {
    s.lambda = cloth::dense_spectrum(field, x, zero);
    s.how = "all, dense general solver";
    return s;
  }
  if (dense_damped)
    std::printf("  the dense spectrum of the damped cloth is computed for at most %d unknowns (this grid has %d: "
                "O(n^3) time and O(n^2) memory); its %d largest eigenvalues stand for it\n",
                cloth::dense_general_limit, n, extreme_count);
  s.lambda = cloth::largest_eigenvalues(field, x, zero, extreme_count);
  s.how = "largest, Arnoldi";
  return s;
}

void write_points(const std::string& path, const std::string& header, const std::vector<Complex>& lambda, double h) {
  cloth::OutputFile out(path);
  std::fprintf(out.get(), "# %s: Re, Im\n", header.c_str());
  for (const Complex& l : lambda) std::fprintf(out.get(), "%.8g %.8g\n", h * l.real(), h * l.imag());
  out.commit();
}

}  // namespace

std::vector<std::pair<std::string, std::string>> report_spectra(const std::string& dir, const SceneParams& scene,
                                                                const RestSpectrum& rest, Equilibria& equilibria,
                                                                double h, bool dense_damped, int threads) {
  if (rest.exact)
    std::printf("rest state: %zu eigenvalues of L in [%.3g, %.4f]; %d of them are zero (the flat sheet has no "
                "out-of-plane stiffness)\n", rest.mu.size(), rest.mu.front(), rest.mu_max, rest.zero_count);
  else
    std::printf("rest state: largest eigenvalue of L %.4f (Lanczos); the grid is too large for a dense solve, so "
                "the rest spectrum is drawn from %zu samples of [0, %.4f]\n", rest.mu_max, rest.mu.size(), rest.mu_max);
  std::vector<std::pair<std::string, std::string>> summary = {{"rest_L_max_eigenvalue", cloth::format_number(rest.mu_max)}};
  const std::vector<std::pair<double, double>> report_cases = {{50, 0}, {200, 0}, {200, 20}};
  equilibria.prepare({50, 200}, threads);
  for (const auto& [K, D] : report_cases) {
    const std::string tag = "K" + cloth::format_number(K) + "_D" + cloth::format_number(D);
    std::vector<Complex> at_rest;
    double rest_largest = 0;
    for (const Mode& mode : rest_modes(rest, K, D, scene.mass))
      for (const Complex& l : mode) {
        at_rest.push_back(l);
        rest_largest = std::max(rest_largest, std::abs(l));
      }
    write_points(dir + "/spectrum_rest_" + tag + ".dat", "h lambda at the rest state, h = " + cloth::format_number(h),
                 at_rest, h);

    const Scene s(with_stiffness(scene, K, D));
    ForceField field(s);
    const cloth::Equilibrium& eq = equilibria.at(K);
    const SaggedSpectrum sagged = sagged_spectrum(field, eq.x, D, dense_damped);
    write_points(dir + "/spectrum_sagged_" + tag + ".dat",
                 "h lambda at the sagged equilibrium (" + sagged.how + "), h = " + cloth::format_number(h), sagged.lambda, h);
    double largest = 0;
    for (const Complex& l : sagged.lambda) largest = std::max(largest, std::abs(l));
    // The power iteration (analysis/power_iteration.hpp) as an independent check of the largest |lambda|.
    const cloth::PowerIterationResult pw = cloth::largest_eigenvalue_magnitude(field, eq.x, Vector::Zero(eq.x.size()));
    std::printf("K = %g, D = %g: sag %.3f m; max |lambda| rest %.2f, sagged %.2f (%s), power iteration %.2f in %d "
                "iterations; h max|lambda| = %.3f\n",
                K, D, -eq.x.minCoeff(), rest_largest, largest, sagged.how.c_str(), pw.magnitude, pw.iterations,
                h * largest);
    summary.emplace_back("sag_" + tag, cloth::format_number(-eq.x.minCoeff()));
    summary.emplace_back("max_abs_lambda_rest_" + tag, cloth::format_number(rest_largest));
    summary.emplace_back("max_abs_lambda_sagged_" + tag, cloth::format_number(largest));
    summary.emplace_back("power_iteration_sagged_" + tag, cloth::format_number(pw.magnitude));
  }
  return summary;
}

}  // namespace ch07
