// Implicit Euler with contact enforced inside the linear solve (Baraff & Witkin 1998, section 5), Chapter 11: a
// particle touching an obstacle has its normal velocity prescribed and its other two directions solved for, by
// the filtered conjugate gradients of integrators/filtered_pcg.hpp; contacts enter and leave between steps.
#pragma once

#include "contact/obstacles.hpp"
#include "integrators/filtered_pcg.hpp"
#include "integrators/stepper.hpp"

#include <vector>

namespace cloth {

/// How far the filtered step iterates: Baraff and Witkin's single iteration (max_iterations = 1), or Newton's
/// iteration on the definite matrix until its update |ddv|_inf <= tolerance (1 + |v1|_inf), every iteration
/// filtered with the same constrained set.
struct FilteredNewton {
  int max_iterations = 1;
  double tolerance = 1e-8;
};

/// Baraff and Witkin's step: one Newton iteration of implicit Euler from the guess v1 = v0,
///   A dv = h f(x0 + h v0, v0),  A = M - h df/dv - h^2 df/dx (the definite treatment, so CG applies),
/// v1 = v0 + dv, x1 = x0 + h v1 (or Newton's iteration to convergence, FilteredNewton), solved with the constraints of the particles in contact:
///  - a particle enters when it lies within the thickness of an obstacle and does not move away from it: its
///    component along the normal n is prescribed, dv . n = -v0 . n, so that it ends the step with v1 . n = 0;
///  - the constraint's impulse is the filtered-out residual, e = (I - S)(A dv - b), of normal size j_n = e . n:
///    pushing (j_n >= 0), it is the normal impulse that bounds friction, |dv_t| <= mu j_n / m by Coulomb's cone;
///    pulling (j_n < 0), the obstacle would be holding the cloth back, and the particle is released for the next
///    step (Baraff & Witkin's release rule);
///  - a particle that was not constrained and ends the step inside an obstacle is corrected as the explicit
///    steps are (resolve_obstacle_contacts), and enters the constrained set at the next step.
class ContactImplicitEuler final : public Stepper {
 public:
  /// The model must pass validate(ContactModel). cg_tolerance is the relative residual of each filtered solve.
  ContactImplicitEuler(ForceField& field, ContactModel model, FilteredNewton newton = {},
                       double cg_tolerance = 1e-10, int cg_max_iterations = 2000);

  /// Baraff and Witkin's step is implicit Euler linearised: the registry's name of the method it approximates.
  [[nodiscard]] std::string name() const override { return "implicit_euler"; }
  bool step(double h, Vector& x, Vector& v) override;

  [[nodiscard]] const ContactModel& model() const { return model_; }
  /// Particles constrained in the last step, and those of them released at its end.
  [[nodiscard]] int constrained() const { return constrained_; }
  [[nodiscard]] int released() const { return released_; }

 private:
  void choose_constraints(const Vector& x, const Vector& v);
  bool solve_filtered(double h, const Vector& x, const Vector& v);
  void apply_impulses(Vector& v);

  ContactModel model_;
  FilteredNewton newton_;
  double cg_tolerance_;
  int cg_max_iterations_;
  SparseMatrix A_;
  FilteredPCG pcg_;
  ConstraintFilter filter_;
  Vector x_guess_, v_guess_, b_, z_, zero_, dv_, ddv_, e_, x0_;
  std::vector<Eigen::Vector3d> normal_;  // the constrained normal of each particle (zero when free)
  std::vector<char> released_flag_;      // released at the end of the last step: not constrained in the next
  int constrained_ = 0;
  int released_ = 0;
};

}  // namespace cloth
