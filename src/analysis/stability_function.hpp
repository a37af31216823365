// Linear stability theory of the book's integrators (Chapter 7): the stability function R(z) of a Runge-Kutta
// method computed from its Butcher tableau, implicit Euler's 1/(1 - z), and symplectic Euler's amplification of
// one damped oscillator mode, which is a 2 x 2 matrix rather than a scalar function of z.
#pragma once

#include "integrators/butcher_tableau.hpp"

#include <complex>
#include <functional>
#include <vector>

namespace cloth {

using Complex = std::complex<double>;

/// R(z) = 1 + z b^T (I - z A)^{-1} 1: one step of the tableau's method applied to y' = lambda y multiplies y by
/// R(h lambda) (Hairer & Wanner 1996, IV.2). Computed from A and b, never typed in; for an explicit tableau it is
/// the polynomial sum_k z^k b^T A^{k-1} 1.
Complex stability_function(const ButcherTableau& tableau, Complex z);

/// The coefficients r_0..r_s of R(z) = sum_k r_k z^k for an explicit (strictly lower triangular) tableau:
/// r_0 = 1, r_k = b^T A^{k-1} 1, since (I - z A)^{-1} = sum_k z^k A^k when A is nilpotent. For evaluating R at
/// many points; equal to stability_function() to rounding.
std::vector<double> stability_polynomial(const ButcherTableau& tableau);

/// R(infinity), the limit of R(z) as |z| grows: how much of a mode far stiffer than 1/h survives a step. 0 for an
/// L-stable method (backward Euler, the SDIRKs), -1 for implicit midpoint and the trapezoid rule, whose stiff
/// modes flip sign each step and never decay. R is a rational function of degree s, so R(z) = R_inf + c1 / z +
/// c2 / z^2 + ...; three evaluations far out (z = -1e4, -2e4, -4e4) give R_inf to about 1e-11 by Richardson
/// extrapolation, whether or not A is invertible (an ESDIRK's is not). Infinite for an explicit tableau.
double stability_at_infinity(const ButcherTableau& tableau);

/// The largest |R(iy)| over the imaginary axis, sampled at y = tan(theta) for `samples` angles theta in [0, pi/2)
/// (R has real coefficients, so R(-iy) is the conjugate of R(iy)), plus R(infinity).
double imaginary_axis_maximum(const ButcherTableau& tableau, int samples = 4000);

/// A-stability (|R(z)| <= 1 on the whole left half-plane), by the maximum principle: R has no pole there (its
/// poles are 1/lambda for the eigenvalues lambda != 0 of A, so every eigenvalue needs Re lambda >= 0, and none on
/// the axis) and |R(iy)| <= 1 + 1e-12 on the imaginary axis (Hairer & Wanner 1996, IV.3).
bool a_stable(const ButcherTableau& tableau);

/// Implicit Euler on y' = lambda y: y1 = y0 / (1 - z), so R(z) = 1 / (1 - z); A-stable (|R| <= 1 for Re z <= 0).
Complex implicit_euler_stability(Complex z);

/// Symplectic Euler on one mode x'' = a x + b x' (v1 = v0 + h (a x0 + b v0), x1 = x0 + h v1) multiplies (x, v) by
/// the 2 x 2 matrix [[1 + h^2 a, h (1 + h b)], [h a, 1 + h b]]; this returns its spectral radius. The mode's two
/// eigenvalues lambda1, lambda2 as a first-order system fix a = -lambda1 lambda2 and b = lambda1 + lambda2, so the
/// arguments are z1 = h lambda1 and z2 = h lambda2 (a conjugate pair for an underdamped mode).
double symplectic_euler_amplification(Complex z1, Complex z2);

/// The Jury conditions for that matrix (trace T = 2 + h^2 a + h b, determinant 1 + h b): stable when
/// |1 + h b| <= 1 and |T| <= 1 + (1 + h b). For an undamped oscillator (b = 0, a = -omega^2) this is h omega <= 2.
bool symplectic_euler_stable(double h2a, double hb);

/// The largest t in [0, t_max] such that stable(s) holds for every s in [0, t] sampled by bisection: the edge of
/// a stability interval along a ray. Bisects `iterations` times after a coarse scan of `scan` points, so that a
/// region that is left and re-entered (as RK4's is near the imaginary axis) is not mistaken for a connected one.
double stability_limit_along(const std::function<bool(double)>& stable, double t_max, int scan = 400,
                             int iterations = 60);

}  // namespace cloth
