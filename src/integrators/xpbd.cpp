// XPBD (Macklin, Müller & Chentanez 2016) on the book's springs, and small steps (Macklin et al. 2019).
//
// The springs as compliant constraints. A spring of stiffness K has the energy K/2 C^2 with C = l - L0, which XPBD
// writes as 1/(2 alpha) C^2 with the compliance alpha = 1/K. The spring force on p, K (L0 - l) u, is then
// -alpha^-1 C grad_p C with grad_p C = u. Implicit Euler's positions x solve
//   M (x - x~) = h^2 f(x, (x - x^n)/h),   x~ = x^n + h v^n + h^2 g,
// and with one multiplier per spring, lambda_j = h^2 times its force along u_j, this is the pair of equations
// of Macklin et al. (2016), with the damping term they add to the second:
//   g(x, lambda) = M (x - x~) - sum_j grad C_j(x)^T lambda_j = 0,
//   h_j(x, lambda) = C_j(x) + alpha~_j lambda_j + gamma_j grad C_j(x) (x - x^n) = 0,
// alpha~ = alpha / h^2 = 1 / (K h^2). The book's projected damper -D ((v_p - v_q) . u) u is exactly their
// Rayleigh damper beta grad C^T grad C v with beta = D (grad C v is the stretching rate (v_p - v_q) . u), so with
// beta~ = h^2 beta their damping ratio is gamma = alpha~ beta~ / h = D / (K h). The report's law
// -D (v_p - v_q) l is not of that form (it damps every relative motion, not the stretching rate) and is refused.
//
// XPBD's iteration. Newton's method on (g, h) would solve with the matrix [[K_g, -grad C^T], [grad C, alpha~]],
// K_g = M - sum_j lambda_j d^2 C_j / dx^2. Macklin et al. take two shortcuts in that Newton step: K_g ~ M (the
// constraints' curvature dropped) and g(x_i, lambda_i) = 0 (the momentum residual assumed zero at every iterate).
// Then dx = M^-1 grad C^T dlambda, the multipliers solve (grad C M^-1 grad C^T + alpha~) dlambda = -h (with
// (1 + gamma) on the first term when damped), and a Gauss-Seidel sweep over its rows, each with C and grad C
// evaluated at the positions of the moment, is their eq. (26): project_distance_constraint in xpbd.hpp.
//
// What the second shortcut costs. Each projection of spring j moves its particles along the direction u_j had
// at that moment, x^{j,k}; the multiplier, though, is summed into lambda_j as if it acted along the final
// direction. At a converged fixed point every h_j = 0 holds exactly (the constraints and their compliance are
// met), but the momentum equation is left with the residual
//   r = M (x - x~) - sum_j grad C_j(x)^T lambda_j = sum_j sum_k (grad C_j(x^{j,k}) - grad C_j(x))^T dlambda_{j,k}:
// the multipliers times how far each spring turned while the iteration went on. Since lambda_j = h^2 (force
// along u_j) at the fixed point, r is exactly implicit Euler's residual at XPBD's answer,
//   r = M (x - x~) - h^2 f(x, (x - x^n)/h),
// and XPBD's converged step differs from implicit Euler's by dx = A^-1 r + O(|r|^2), A = M - h df/dv - h^2 df/dx
// the Newton matrix of the step: the gap Chapter 10 measures (tests/test_xpbd.cpp checks dx against A^-1 r).
// With lambda_j ~ h^2 T_j (T_j its tension) and, were the iterates to move straight from x~ to x, a turn of order
// h^2 |a_perp| / L0 (a_perp the relative acceleration of its ends across it), |r| ~ h^4 T |a_perp| / L0: set by the
// load rather than by K, and of higher order in h than implicit Euler's own local error. Where h^2 K / m is large
// the Gauss-Seidel iterates overshoot along chains of stiff springs and the springs turn further; Chapter 10
// measures the gap (ch10_xpbd) and finds it near 1 % of the step's motion at h = 1/60 s.
//
// Gauss-Seidel, not Jacobi: each projection sees the positions the ones before it moved, so information crosses
// the whole cloth within one sweep in the springs' order (structural, then shear, then flexion, each in grid
// order), and no under-relaxation is needed. The result depends on that order (a different order is a
// different, equally valid, iteration); a Jacobi sweep would project every spring from the same positions and
// average, order-free and parallel, but it converges more slowly and overshoots without relaxation.
#include "integrators/xpbd.hpp"

#include "model/bending.hpp"

#include "base/input_error.hpp"

#include <algorithm>
#include <utility>

namespace cloth {

Xpbd::Xpbd(ForceField& field, std::string name, int iterations, int substeps)
    : Stepper(field), name_(std::move(name)), iterations_(iterations), substeps_(substeps) {
  const Scene& scene = field.scene();
  if (iterations < 1) throw InputError(name_ + ": iterations: expected a whole number >= 1");
  if (substeps < 1) throw InputError(name_ + ": substeps: expected a whole number >= 1");
  if (scene.has_damping() && scene.params().damping_model != DampingModel::projected)
    throw InputError("the report's damping law -D (v_p - v_q) l is not a damper along the springs, which is all "
                     "XPBD's constraints can damp: expected --damping-model projected");
  free_count_ = scene.free_count();
  inverse_mass_ = 1.0 / scene.params().mass;
  const Eigen::Index slots = scene.particle_count();
  // The pinned tail holds the rest positions and never moves: its inverse mass is 0 (slot >= free_count_).
  X_ = scene.rest_positions().reshaped(3, slots);
  previous_ = X_;
  V_.setZero(3, slots);
  lambda_.assign(scene.springs().springs.size(), 0.0);
  if (field.bending() != nullptr) bending_force_.setZero(3 * free_count_);
}

bool Xpbd::step(double h, Vector& x, Vector& v) {
  X_.leftCols(free_count_) = x.reshaped(3, free_count_);
  V_.leftCols(free_count_) = v.reshaped(3, free_count_);
  const double s = h / substeps_;
  for (int k = 0; k < substeps_; ++k) substep(s);
  x.reshaped(3, free_count_) = X_.leftCols(free_count_);
  v.reshaped(3, free_count_) = V_.leftCols(free_count_);
  ++counters_.steps;
  return true;
}

void Xpbd::substep(double s) {
  const Scene& scene = field_.scene();
  const Eigen::Index n = free_count_;
  // [xpbd_substep]
  // The inertial prediction x~ = x^n + s v^n + s^2 g, from which the constraints pull the particles back
  // (Macklin et al. 2016, Algorithm 1). lambda starts at 0 in every substep.
  previous_.leftCols(n) = X_.leftCols(n);
  V_.row(2).head(n).array() -= s * scene.params().gravity;
  // A bending term (Chapter 12) is no distance constraint: it enters the prediction as a force at x^n, as
  // gravity does, explicitly.
  if (BendingEnergy* bending = field_.bending()) {
    bending_force_.setZero();
    bending->add_forces(Eigen::Map<const Vector>(X_.data(), 3 * n), bending_force_);
    V_.leftCols(n) += (s * inverse_mass_) * bending_force_.reshaped(3, n);
  }
  X_.leftCols(n) += s * V_.leftCols(n);
  std::fill(lambda_.begin(), lambda_.end(), 0.0);
  for (int it = 0; it < iterations_; ++it) {
    for (SpringFamily family : all_spring_families) {
      const SpringRange r = scene.springs().family[static_cast<int>(family)];
      const double alpha_tilde = 1.0 / (scene.stiffness(family) * s * s);  // alpha / s^2, alpha = 1/K
      const double gamma = scene.damping(family) / (scene.stiffness(family) * s);  // alpha~ beta~ / s, beta = D
      for (int j = r.begin; j < r.end; ++j) {
        const Spring& sp = scene.springs().springs[static_cast<std::size_t>(j)];
        const double w_p = sp.p < free_count_ ? inverse_mass_ : 0.0;
        const double w_q = sp.q < free_count_ ? inverse_mass_ : 0.0;
        project_distance_constraint(X_.col(sp.p), X_.col(sp.q), previous_.col(sp.p), previous_.col(sp.q), w_p, w_q,
                                    sp.rest_length, alpha_tilde, gamma, lambda_[static_cast<std::size_t>(j)]);
      }
    }
  }
  if (contact_ != nullptr) {  // contacts last, so that no spring projection pushes a particle back in
    const auto free_coordinates = static_cast<Eigen::Index>(3 * n);
    project_obstacle_contacts(*contact_, Eigen::Map<const Eigen::VectorXd>(previous_.data(), free_coordinates),
                              Eigen::Map<Eigen::VectorXd>(X_.data(), free_coordinates));
  }
  // The velocity the positions imply, as implicit Euler's v = (x - x^n) / s.
  V_.leftCols(n) = (X_.leftCols(n) - previous_.leftCols(n)) / s;
  // [xpbd_substep]
}

}  // namespace cloth
