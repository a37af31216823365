// Baraff and Witkin's implicit step with contact constraints filtered inside conjugate gradients.
#include "integrators/contact_implicit_euler.hpp"

#include "base/format_number.hpp"

#include <utility>

namespace cloth {

ContactImplicitEuler::ContactImplicitEuler(ForceField& field, ContactModel model, double cg_tolerance,
                                           int cg_max_iterations)
    : Stepper(field), model_(std::move(model)), cg_tolerance_(cg_tolerance), cg_max_iterations_(cg_max_iterations),
      A_(field.pattern()), pcg_(field.dof_count()), filter_(field.scene().free_count()),
      x_guess_(field.dof_count()), b_(field.dof_count()), z_(field.dof_count()), dv_(field.dof_count()),
      e_(field.dof_count()), x0_(field.dof_count()),
      normal_(static_cast<std::size_t>(field.scene().free_count()), Eigen::Vector3d::Zero()),
      released_flag_(static_cast<std::size_t>(field.scene().free_count()), 0) {
  validate(model_);
}

// [contact_implicit_step]
bool ContactImplicitEuler::step(double h, Vector& x, Vector& v) {
  const int particles = field_.scene().free_count();
  const double m = field_.scene().params().mass;
  // Which particles are constrained this step, and to what: touching, not leaving, not just released.
  filter_.clear();
  z_.setZero();
  constrained_ = 0;
  for (int s = 0; s < particles; ++s) {
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
  // One Newton iteration from v1 = v0: A dv = b with b = h f(x0 + h v0, v0), the residual there.
  x_guess_ = x + h * v;
  field_.forces(x_guess_, v, b_);
  b_ *= h;
  field_.newton_matrix(x_guess_, v, h, StiffnessTreatment::definite, A_);
  ++counters_.rhs_evaluations;
  ++counters_.jacobian_assemblies;
  if (!pcg_.compute(A_)) {
    failure_ = {StepFailureKind::cg_not_converged, "a diagonal block of the Newton matrix is not positive definite"};
    return false;
  }
  dv_.setZero();
  const bool converged = pcg_.solve(A_, b_, filter_, z_, dv_, cg_tolerance_, cg_max_iterations_);
  ++counters_.linear_solves;
  counters_.cg_iterations += pcg_.iterations();
  if (!converged) {
    failure_ = {StepFailureKind::cg_not_converged, "filtered CG did not reach its tolerance in " +
                                                       std::to_string(pcg_.iterations()) + " iterations"};
    return false;
  }
  // The constraints' impulses: the part of A dv - b the filter removed.
  e_.noalias() = A_ * dv_;
  e_ -= b_;
  filter_.apply_complement(e_);
  x0_ = x;
  v += dv_;
  released_ = 0;
  for (int s = 0; s < particles; ++s) {
    const Eigen::Vector3d& n = normal_[static_cast<std::size_t>(s)];
    released_flag_[static_cast<std::size_t>(s)] = 0;
    if (n.isZero()) continue;
    const double j_n = e_.segment<3>(3 * s).dot(n);  // the normal impulse the obstacle gave [N s]
    if (j_n < 0) {  // it pulled: release the particle for the next step
      released_flag_[static_cast<std::size_t>(s)] = 1;
      ++released_;
      continue;
    }
    // Coulomb's cone on the tangential velocity, with the constraint's impulse per unit mass as the bound.
    const Eigen::Vector3d v_t = v.segment<3>(3 * s) - v.segment<3>(3 * s).dot(n) * n;
    const double speed = v_t.norm();
    const double bound = j_n / m;
    if (speed <= model_.friction.mu_s * bound) v.segment<3>(3 * s) -= v_t;
    else v.segment<3>(3 * s) -= (model_.friction.mu_k * bound / speed) * v_t;
  }
  x += h * v;
  // Contacts that began during the step: corrected as the explicit methods' are, constrained from the next step.
  resolve_obstacle_contacts(model_, x0_, x, v);
  ++counters_.steps;
  return true;
}
// [contact_implicit_step]

}  // namespace cloth
