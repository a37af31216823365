// The spectrum of the linearised cloth (Chapter 7): the eigenvalues lambda of the first-order system
// y' = J y, J = [[0, I], [M^{-1} df/dx, M^{-1} df/dv]], y = (dx, dv), built from the model's own Jacobians, and
// the sagged static equilibrium about which the cloth is linearised.
#pragma once

#include "model/force_field.hpp"
#include "analysis/power_iteration.hpp"

#include <array>
#include <complex>
#include <vector>

namespace cloth {

/// Up to this many unknowns (n = 3 n_free) a dense symmetric eigen-solve of an n x n matrix is cheap (under a
/// few seconds; the 20 x 20 cloth has 1188). Beyond it, only extreme eigenvalues are computed, by Lanczos and
/// Arnoldi on sparse products.
inline constexpr int dense_symmetric_limit = 3000;

/// Up to this many unknowns the dense non-symmetric eigen-solve of the 2n x 2n matrix J is attempted at all
/// (the 20 x 20 cloth: 2376 x 2376, minutes; the cost grows like n^3 and the memory like n^2).
inline constexpr int dense_general_limit = 1200;

/// The dense 2n x 2n matrix J at (x, v); n = 3 n_free. For small grids only (a 20 x 20 cloth gives 2376 x 2376).
Eigen::MatrixXd linearised_system(ForceField& field, const Vector& x, const Vector& v);

/// Every eigenvalue of J, by Eigen's dense non-symmetric eigen-solver (O(n^3): small grids).
std::vector<std::complex<double>> dense_spectrum(ForceField& field, const Vector& x, const Vector& v);

/// The eigenvalues omega^2 of -M^{-1} df/dx at (x, v = 0), ascending, by the symmetric eigen-solver: with v = 0
/// the damper adds nothing to df/dx, so df/dx is the (symmetric) Hessian of -E. A negative omega^2 is a buckling
/// direction (a compressed spring's transverse term).
std::vector<double> stiffness_eigenvalues(ForceField& field, const Vector& x);

/// The two eigenvalues of one mode x'' = -omega^2 x - c x', roots of lambda^2 + c lambda + omega^2 = 0.
std::array<std::complex<double>, 2> mode_eigenvalues(double omega2, double c);

/// The spectrum of J when df/dv = beta df/dx (damping proportional to stiffness, as at the rest state, where
/// both are Laplacians of the same springs: df/dx = -K L, df/dv = -D L, beta = D/K): every omega^2 gives a mode
/// with c = beta omega^2. Exact then, and cheap: one symmetric eigenproblem serves every (K, D).
std::vector<std::complex<double>> proportional_spectrum(const std::vector<double>& omega2, double beta);

/// The `count` largest eigenvalues omega^2 of -M^{-1} df/dx at (x, v = 0), descending, by Lanczos (Spectra's
/// SymEigsSolver) on sparse products: the fast end of stiffness_eigenvalues() for grids too large for it.
std::vector<double> largest_stiffness_eigenvalues(ForceField& field, const Vector& x, int count);

/// The `count` eigenvalues of largest |lambda| of J at (x, v), by the implicitly restarted Arnoldi method
/// (Spectra's GenEigsSolver; Lehoucq, Sorensen & Yang 1998) on sparse products with df/dx and df/dv, without
/// forming J. Conjugate pairs come whole (count is raised by one if it would split a pair); sorted by
/// decreasing |lambda|. Empty if Arnoldi does not converge.
std::vector<std::complex<double>> largest_eigenvalues(ForceField& field, const Vector& x, const Vector& v, int count);

/// Largest |lambda| of J at (x, v) without forming J: power iteration (analysis/power_iteration.hpp) on sparse
/// products with df/dx and df/dv. The dominant eigenvalues of a real J are often a conjugate pair, which the
/// iteration's two-term fit resolves. Stops when the estimate changes by less than `tolerance` relatively over
/// 10 iterations.
PowerIterationResult largest_eigenvalue_magnitude(ForceField& field, const Vector& x, const Vector& v,
                                                  double tolerance = 1e-6, int max_iterations = 5000);

/// The static equilibrium f(x, 0) = 0 the cloth sags to under gravity.
struct Equilibrium {
  Vector x;
  int iterations = 0;
  double residual = 0;  ///< |f|_inf at x [N]
  bool converged = false;
};

/// Finds it by pseudo-time stepping: from the rest state, repeated implicit Euler steps of length tau from rest
/// (velocity reset each step), (M - tau^2 df/dx) dx = tau^2 f, which is Newton's method regularised by M / tau^2.
/// tau doubles while the energy falls and shrinks when it would rise, so the iteration turns into Newton's method
/// near the minimum; where the exact Hessian is indefinite (a stiff sheet buckling), the definite step is taken and
/// doubled while the energy keeps falling. Converged when |f|_inf <= tolerance m g, or when it is at the rounding level of the spring
/// forces, 64 eps K 2d (the larger K of the families), which a very light cloth's weight may be below.
Equilibrium static_equilibrium(ForceField& field, double tolerance = 1e-9, int max_iterations = 300);

}  // namespace cloth
