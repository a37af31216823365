// Chapter 7, part 2: the spectrum of the linearised cloth at its rest state and at its sagged equilibrium, with
// dense eigen-solvers where the grid is small enough for them to be cheap and Lanczos or Arnoldi for the
// extreme eigenvalues elsewhere.
#pragma once

#include "stability_regions.hpp"

#include "analysis/spectrum.hpp"
#include "model/scene.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ch07 {

/// The eigenvalues mu of the longitudinal Laplacian L = sum u u^T of the flat sheet, with which df/dx = -K L and
/// df/dv = -D L at the rest state. `exact`: every eigenvalue, from a dense symmetric solve. Otherwise the grid is
/// too large for that, and mu samples [0, mu_max] evenly (mu_max by Lanczos): the rest spectrum lies on the
/// curve that mu traces, so the samples give the same picture and a prediction that is, if anything, cautious.
struct RestSpectrum {
  std::vector<double> mu;
  double mu_max = 0;
  bool exact = true;
  int zero_count = 0;  ///< zero eigenvalues (exact only): directions with no stiffness at all
};
RestSpectrum rest_spectrum(const cloth::SceneParams& scene);

/// The modes lambda^2 + (D mu / m) lambda + K mu / m = 0 of the rest state at stiffness K and damping D.
std::vector<Mode> rest_modes(const RestSpectrum& rest, double K, double D, double m);

/// The sagged equilibria of the scene, one per stiffness (damping does not move it), computed once each.
class Equilibria {
 public:
  explicit Equilibria(cloth::SceneParams scene) : scene_(std::move(scene)) {}
  const cloth::Equilibrium& at(double K);
  /// Computes the equilibria of every stiffness not yet known, on `threads` threads (they are independent).
  void prepare(const std::vector<double>& stiffnesses, int threads);

 private:
  cloth::SceneParams scene_;
  std::map<double, cloth::Equilibrium> by_stiffness_;
};

/// The `count` eigenvalues of largest |lambda| of the linearised cloth at (x, v = 0) with damping D: undamped,
/// +-i omega from the largest omega^2 (Lanczos on the n x n symmetric -M^{-1} df/dx); damped, Arnoldi on the
/// 2n x 2n first-order system.
std::vector<Complex> largest_eigenvalues(cloth::ForceField& field, const cloth::Vector& x, double D, int count);

/// The modes of the sagged cloth that decide stability: its `count` eigenvalues of largest |lambda|, by Arnoldi
/// (cloth::largest_eigenvalues). Real eigenvalues stand alone ({lambda, lambda}); `pairs_only` keeps only
/// conjugate pairs (what symplectic Euler needs) and gives nothing when the dominant eigenvalue is real.
std::vector<Mode> modes_of(const std::vector<Complex>& lambda, bool pairs_only);

/// The report's three (K, D) cases: their rest and sagged spectra times h, written to spectrum_rest_*.dat and
/// spectrum_sagged_*.dat and printed. The sagged spectrum is dense (undamped: the symmetric solver; damped: the
/// general one, with `dense_damped` only) where the grid is small enough, its largest eigenvalues otherwise.
std::vector<std::pair<std::string, std::string>> report_spectra(const std::string& dir, const cloth::SceneParams& scene,
                                                                const RestSpectrum& rest, Equilibria& equilibria,
                                                                double h, bool dense_damped, int threads);

/// The scene with stiffness K and damping D.
cloth::SceneParams with_stiffness(cloth::SceneParams scene, double K, double D);

}  // namespace ch07
