// Rest and sagged spectra of the cloth for Chapter 7.
#include "cloth_spectrum.hpp"

#include "base/format_number.hpp"
#include "model/report_cases.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/parallel_runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace ch07 {

using cloth::ForceField;
using cloth::Scene;
using cloth::SceneParams;
using cloth::Vector;

RestSpectrum rest_spectrum(const SceneParams& scene) {
  // L is -M^{-1} df/dx of the flat sheet with K = 1, times m.
  const SceneParams unit = cloth::with_K_and_D(scene, 1.0, 0.0);
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
  prepare({K}, 1);
  return by_stiffness_.at(K);
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
  cloth::run_in_parallel(missing.size(), threads, [&](std::size_t k) {
    cloth::throw_if_interrupted();
    const Scene scene(cloth::with_K_and_D(scene_, missing[k], 0.0));
    ForceField field(scene);
    found[k] = cloth::static_equilibrium(field);
  });
  for (std::size_t k = 0; k < missing.size(); ++k) {
    // Every sagged prediction linearises about the equilibrium: without it there is nothing to predict from.
    if (!found[k].converged)
      throw NoEquilibrium("the sagged equilibrium for K = " + cloth::format_number(missing[k]) + " did not converge (|f| = " +
                          cloth::format_number(found[k].residual, 3) + " N after " +
                          std::to_string(found[k].iterations) + " iterations): the sagged spectra and h_max are "
                          "predicted about it");
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

}  // namespace ch07
