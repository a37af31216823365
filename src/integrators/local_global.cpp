// Local/global iterations for the implicit Euler step (Liu, Bargteil, O'Brien & Kavan 2013).
//
// Implicit Euler's new positions x minimise g(x) = 1/(2 h^2) (x - y)^T M (x - y) + E(x), with the inertial target
// y = x0 + h v0 + h^2 g (gravity) and E the springs' energy (setting g's gradient to zero gives
// M (v1 - v0) = h f(x1) with v1 = (x1 - x0) / h). Each spring's energy is a minimum over a free vector d of
// length L0:  k/2 (|x_p - x_q| - L0)^2 = min_{|d| = L0} k/2 |x_p - x_q - d|^2. Minimising alternately over the d's
// (local: d = L0 (x_p - x_q) / |x_p - x_q|, each spring on its own) and over x (global: the linear system
//   (M + h^2 L) x = M y + h^2 J d,   L = sum k (e_p - e_q)(e_p - e_q)^T,   J d = sum k (e_p - e_q) d,
// one matrix for all three coordinates, constant for a given h) lowers g at every iteration, so the iterates
// converge to implicit Euler's step.
//
// Damping is not an energy. It enters the global right-hand side as the force h^2 f_D(x_k, (x_k - x0) / h) at the
// current iterate: a fixed point of the iteration is then exactly implicit Euler's step with damping (the
// paper adds damping differently, as a velocity correction; this way the limit is the same as Newton's).
#include "integrators/local_global.hpp"

#include "model/bending.hpp"

#include "base/input_error.hpp"

#include <cmath>
#include <vector>

namespace cloth {

LocalGlobal::LocalGlobal(ForceField& field, int iterations) : Stepper(field), iterations_(iterations) {
  if (iterations < 1) throw InputError("local/global iterations: expected a whole number >= 1");
  const int n = field.scene().free_count();
  pinned_pull_.setZero(n, 3);
  y_.setZero(n, 3), b_.setZero(n, 3), X_.setZero(n, 3), scratch_.setZero(n, 3), x0_.setZero(n, 3);
}

std::string LocalGlobal::name() const { return "local_global"; }

bool LocalGlobal::factor(double h) {
  const Scene& scene = field_.scene();
  const int n = scene.free_count();
  const double m = scene.params().mass;
  const double h2 = h * h;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(n) + 4 * scene.springs().springs.size());
  for (int s = 0; s < n; ++s) triplets.emplace_back(s, s, m);
  pinned_pull_.setZero();
  const Eigen::VectorXd& rest = scene.rest_positions();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = scene.springs().family[static_cast<int>(family)];
    const double h2k = h2 * scene.stiffness(family);
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = scene.springs().springs[static_cast<std::size_t>(k)];
      const bool p_free = s.p < n, q_free = s.q < n;
      if (p_free) triplets.emplace_back(s.p, s.p, h2k);
      if (q_free) triplets.emplace_back(s.q, s.q, h2k);
      if (p_free && q_free) {
        triplets.emplace_back(s.p, s.q, -h2k);
        triplets.emplace_back(s.q, s.p, -h2k);
      }
      // A pinned end is a known position: its share of L x moves to the right-hand side.
      if (p_free && !q_free) pinned_pull_.row(s.p) += h2k * rest.segment<3>(3 * s.q).transpose();
      if (q_free && !p_free) pinned_pull_.row(s.q) += h2k * rest.segment<3>(3 * s.p).transpose();
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  llt_.compute(A);
  ++counters_.factorizations;
  factored_h_ = h;
  if (llt_.info() != Eigen::Success) {
    failure_ = {StepFailureKind::factorization_singular, "local/global: M + h^2 L is not positive definite"};
    return false;
  }
  return true;
}

bool LocalGlobal::step(double h, Vector& x, Vector& v) {
  if (h != factored_h_ && !factor(h)) return false;
  const Scene& scene = field_.scene();
  const int n = scene.free_count();
  const double m = scene.params().mass;
  const double h2 = h * h;
  const Eigen::VectorXd& rest = scene.rest_positions();
  const DampingModel damping_model = scene.params().damping_model;
  const bool damped = scene.has_damping();

  x0_ = x.reshaped(3, n).transpose();
  // The inertial target y = x0 + h v0 + h^2 g, and the first iterate x = y (Liu et al.).
  y_ = x0_ + h * v.reshaped(3, n).transpose();
  y_.col(2).array() -= h2 * scene.params().gravity;
  // A bending term (Chapter 12) is not a spring of the global matrix: it enters the target as a force at x0,
  // as gravity does, explicitly.
  if (BendingEnergy* bending = field_.bending()) {
    bending_force_.setZero(x.size());
    bending->add_forces(x, bending_force_);
    y_ += (h2 / m) * bending_force_.reshaped(3, n).transpose();
  }
  X_ = y_;

  // A particle's position and velocity at the current iterate; a pinned one is at rest.
  const auto position = [&](int slot) -> Eigen::Vector3d {
    return slot < n ? Eigen::Vector3d(X_.row(slot).transpose()) : Eigen::Vector3d(rest.segment<3>(3 * slot));
  };
  const auto velocity = [&](int slot) -> Eigen::Vector3d {
    return slot < n ? Eigen::Vector3d((X_.row(slot) - x0_.row(slot)).transpose() / h) : Eigen::Vector3d::Zero();
  };

  for (int it = 0; it < iterations_; ++it) {
    // [local_global_iteration]
    b_ = m * y_ + pinned_pull_;
    for (SpringFamily family : all_spring_families) {
      const SpringRange r = scene.springs().family[static_cast<int>(family)];
      const double h2k = h2 * scene.stiffness(family);
      const double D = scene.damping(family);
      for (int k = r.begin; k < r.end; ++k) {
        const Spring& s = scene.springs().springs[static_cast<std::size_t>(k)];
        const Eigen::Vector3d d = position(s.p) - position(s.q);
        const double l = d.norm();
        // Local step: the spring's rest-length vector closest to its current one. A spring of no length has no
        // direction; d itself then makes its term vanish, as the force routine's guard does.
        const bool degenerate = l <= degenerate_length_fraction * s.rest_length;
        Eigen::Vector3d c = h2k * (degenerate ? d : Eigen::Vector3d((s.rest_length / l) * d));
        if (damped && D != 0.0 && !degenerate) {
          const Eigen::Vector3d w = velocity(s.p) - velocity(s.q);
          if (damping_model == DampingModel::projected) c -= (h2 * D * w.dot(d) / (l * l)) * d;  // -D (w.u) u
          else c -= (h2 * D * l) * w;                                                            // -D w l
        }
        if (s.p < n) b_.row(s.p) += c.transpose();
        if (s.q < n) b_.row(s.q) -= c.transpose();
      }
    }
    // Global step: one solve with the matrix factored once, for the three coordinates together.
    scratch_.noalias() = llt_.permutationP() * b_;
    llt_.matrixL().solveInPlace(scratch_);
    llt_.matrixU().solveInPlace(scratch_);
    X_.noalias() = llt_.permutationPinv() * scratch_;
    // [local_global_iteration]
    ++counters_.linear_solves;
  }
  x.reshaped(3, n) = X_.transpose();
  v.reshaped(3, n) = (X_ - x0_).transpose() / h;
  ++counters_.steps;
  return true;
}

}  // namespace cloth
