// Baraff and Witkin's implicit step with contact constraints filtered inside conjugate gradients, and its Newton
// iteration to convergence with the same filter.
#include "integrators/contact_implicit_euler.hpp"

#include "base/format_number.hpp"

#include <algorithm>
#include <utility>

namespace cloth {

ContactImplicitEuler::ContactImplicitEuler(ForceField& field, ContactModel model, FilteredNewton newton,
                                           double cg_tolerance, int cg_max_iterations)
    : Stepper(field), model_(std::move(model)), newton_(newton), cg_tolerance_(cg_tolerance),
      cg_max_iterations_(cg_max_iterations), A_(field.pattern()), pcg_(field.dof_count()),
      filter_(field.scene().free_count()), x_guess_(field.dof_count()), v_guess_(field.dof_count()),
      b_(field.dof_count()), z_(field.dof_count()), zero_(Vector::Zero(field.dof_count())), dv_(field.dof_count()),
      ddv_(field.dof_count()), e_(field.dof_count()), x0_(field.dof_count()),
      normal_(static_cast<std::size_t>(field.scene().free_count()), Eigen::Vector3d::Zero()),
      released_flag_(static_cast<std::size_t>(field.scene().free_count()), 0) {
  validate(model_);
}

// Which particles are constrained this step, and to what: touching, not leaving, not just released.
void ContactImplicitEuler::choose_constraints(const Vector& x, const Vector& v) {
  filter_.clear();
  z_.setZero();
  constrained_ = 0;
  for (int s = 0; s < field_.scene().free_count(); ++s) {
    auto& n = normal_[static_cast<std::size_t>(s)];
    n.setZero();
    if (released_flag_[static_cast<std::size_t>(s)] != 0) continue;
    for (const Obstacle& obstacle : model_.obstacles) {
      const SurfacePoint surface = surface_point(obstacle, x.segment<3>(3 * s));
      const double v_n = v.segment<3>(3 * s).dot(surface.normal);
      // Touching: within the thickness, up to the rounding of the projection that put it there.
      if (surface.phi <= model_.thickness * (1 + 1e-9) && v_n <= 0) {
        n = surface.normal;
        filter_.constrain(s, n);
        z_.segment<3>(3 * s) = -v_n * n;  // dv . n = -v0 . n: the step ends at rest along n
        ++constrained_;
        break;  // one obstacle per particle: the first it touches
      }
    }
  }
}

// [contact_implicit_step]
bool ContactImplicitEuler::step(double h, Vector& x, Vector& v) {
  choose_constraints(x, v);
  if (!solve_filtered(h, x, v)) return false;
  x0_ = x;
  v += dv_;
  apply_impulses(v);
  x += h * v;
  // Contacts that began during the step: corrected as the explicit methods' are, and constrained from the next step
  // if that left them on the shell (on a plane; on a sphere it lands only to first order, and the correction then
  // keeps holding them).
  resolve_obstacle_contacts(model_, x0_, x, v);
  ++counters_.steps;
  return true;
}
// [contact_implicit_step]

// [filtered_newton]
// Newton's iteration on g(dv) = M dv - h f(x0 + h (v0 + dv), v0 + dv) = 0 from dv = 0: each update solves
// A ddv = -g with A = M - h df/dv - h^2 df/dx (definite) by filtered CG. The first update carries the prescribed
// normal components z; later ones keep them (their constrained components are zero). One iteration is Baraff and
// Witkin's step. On return e_ holds the impulse the filter removed from the last linear solve.
bool ContactImplicitEuler::solve_filtered(double h, const Vector& x, const Vector& v) {
  const double m = field_.scene().params().mass;
  dv_.setZero();
  double first_residual = 0;  // |S b| of the first iteration
  for (int iteration = 0; iteration < newton_.max_iterations; ++iteration) {
    v_guess_ = v + dv_;
    x_guess_ = x + h * v_guess_;
    field_.forces(x_guess_, v_guess_, b_);
    b_ = h * b_ - m * dv_;  // -g(dv)
    field_.newton_matrix(x_guess_, v_guess_, h, StiffnessTreatment::definite, A_);
    ++counters_.rhs_evaluations;
    ++counters_.jacobian_assemblies;
    ++counters_.newton_iterations;
    if (!pcg_.compute(A_)) {
      failure_ = {StepFailureKind::cg_not_converged, "a diagonal block of the Newton matrix is not positive definite"};
      return false;
    }
    // CG's tolerance is relative to the free residual |S b|, which Newton drives towards rounding: later
    // iterations ask for the first one's absolute accuracy instead (at most a tenth of their own residual),
    // so that CG is never asked for digits below rounding.
    e_ = b_;
    filter_.apply(e_);
    const double free_residual = e_.norm();
    if (iteration == 0) first_residual = free_residual;
    const double tolerance =
        iteration == 0 || free_residual == 0
            ? cg_tolerance_
            : std::clamp(cg_tolerance_ * first_residual / free_residual, cg_tolerance_, 0.1);
    ddv_.setZero();
    const bool converged =
        pcg_.solve(A_, b_, filter_, iteration == 0 ? z_ : zero_, ddv_, tolerance, cg_max_iterations_);
    ++counters_.linear_solves;
    counters_.cg_iterations += pcg_.iterations();
    if (!converged) {
      failure_ = {StepFailureKind::cg_not_converged, "filtered CG did not reach its tolerance in " +
                                                         std::to_string(pcg_.iterations()) + " iterations"};
      return false;
    }
    dv_ += ddv_;
    if (newton_.max_iterations == 1 ||
        ddv_.lpNorm<Eigen::Infinity>() <= newton_.tolerance * (1 + (v + dv_).lpNorm<Eigen::Infinity>())) {
      // The constraints' impulses: the part of A ddv + g the filter removed.
      e_.noalias() = A_ * ddv_;
      e_ -= b_;
      filter_.apply_complement(e_);
      return true;
    }
  }
  failure_ = {StepFailureKind::newton_not_converged,
              "filtered Newton did not converge in " + std::to_string(newton_.max_iterations) + " iterations"};
  return false;
}
// [filtered_newton]

// Each constraint's normal impulse j_n = e . n: pulling, the particle is released for the next step (Baraff and
// Witkin's release rule); pushing, it bounds friction by Coulomb's cone, |dv_t| <= mu j_n / m.
void ContactImplicitEuler::apply_impulses(Vector& v) {
  const double m = field_.scene().params().mass;
  released_ = 0;
  for (int s = 0; s < field_.scene().free_count(); ++s) {
    const Eigen::Vector3d& n = normal_[static_cast<std::size_t>(s)];
    released_flag_[static_cast<std::size_t>(s)] = 0;
    if (n.isZero()) continue;
    const double j_n = e_.segment<3>(3 * s).dot(n);  // the normal impulse the obstacle gave [N s]
    if (j_n < 0) {
      released_flag_[static_cast<std::size_t>(s)] = 1;
      ++released_;
      continue;
    }
    const Eigen::Vector3d v_t = v.segment<3>(3 * s) - v.segment<3>(3 * s).dot(n) * n;
    const double speed = v_t.norm();
    const double bound = j_n / m;
    if (speed <= model_.friction.mu_s * bound) v.segment<3>(3 * s) -= v_t;
    else v.segment<3>(3 * s) -= (model_.friction.mu_k * bound / speed) * v_t;
  }
}

}  // namespace cloth
