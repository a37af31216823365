// The dominant eigenvalue of a linear operator by power iteration, one routine for the cloth's fastest rates
// (Chapters 2, 3 and 5: symmetric Jacobians) and for the spectrum of its linearised first-order system
// (Chapter 7: not symmetric, with complex eigenvalues).
#pragma once

#include "model/force_field.hpp"

#include <array>
#include <complex>
#include <functional>

namespace cloth {

/// The roots of mu^2 + p mu + q = 0, the first with +sqrt(p^2 - 4 q).
std::array<std::complex<double>, 2> quadratic_roots(double p, double q);

struct PowerIterationResult {
  double magnitude = 0;
  std::complex<double> dominant;  ///< the root of larger magnitude (Im >= 0 of a conjugate pair)
  int iterations = 0;
  bool converged = false;
};

/// How long the iteration runs: until the magnitude changes by less than `tolerance` relatively over
/// `check_every` iterations, or `max_iterations` (each costs two applications of the operator).
struct PowerIterationSettings {
  double tolerance = 1e-6;
  int check_every = 10;
  int max_iterations = 5000;
};

/// The operator A: out = A y, `out` already sized like y.
using LinearOperator = std::function<void(const Vector& y, Vector& out)>;

/// The eigenvalue of largest magnitude of A, from the start vector `y0` (which must not be orthogonal to its
/// eigenvector). A plain power iteration cannot isolate the dominant eigenvalues of a real A when they are a
/// conjugate pair, and converges slowly when two real ones lie close together (as the cloth's top modes do), so
/// each iteration takes the larger eigenvalue of A restricted to span{y0, A y0}: the larger root of the monic
/// quadratic that minimises |y2 + p y1 + q y0| over three successive iterates (Wilkinson 1965, ch. 9; Saad 2011,
/// ch. 6, two steps of Arnoldi). It converges with the ratio of the third eigenvalue to the first. An A that
/// maps the iterate to zero (A = 0) gives magnitude 0.
PowerIterationResult dominant_eigenvalue(const LinearOperator& apply, Vector y0,
                                         const PowerIterationSettings& settings = {});

}  // namespace cloth
