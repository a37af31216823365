// Newton's method for the implicit Euler step, with the linear solver chosen for the matrix it gets.
#include "integrators/implicit_euler.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"

#include <chrono>
#include <cmath>

namespace cloth {

const NameTable<LinearSolverKind>& linear_solvers() {
  static const NameTable<LinearSolverKind> table(
      "linear solver", {{LinearSolverKind::ldlt, "ldlt"}, {LinearSolverKind::ldu, "ldu"}, {LinearSolverKind::cg, "cg"},
                        {LinearSolverKind::lu, "lu"}, {LinearSolverKind::automatic, "automatic"}});
  return table;
}

const NameTable<NewtonVariant>& newton_variants() {
  static const NameTable<NewtonVariant> table(
      "Newton variant", {{NewtonVariant::full, "full"}, {NewtonVariant::modified, "modified"}, {NewtonVariant::one, "one"}});
  return table;
}

NewtonSettings resolve(NewtonSettings settings, const Scene& scene) {
  if (settings.solver == LinearSolverKind::automatic)
    settings.solver = settings.treatment == StiffnessTreatment::exact && scene.has_damping() ? LinearSolverKind::ldu
                                                                                              : LinearSolverKind::ldlt;
  return settings;
}

void validate(const NewtonSettings& settings, const Scene& scene) {
  const NewtonSettings s = resolve(settings, scene);
  if (!(s.tolerance > 0) || !std::isfinite(s.tolerance))
    throw InputError("Newton tolerance: expected a finite number > 0");
  if (s.max_iterations < 1) throw InputError("Newton iteration limit: expected a whole number >= 1");
  if (s.variant == NewtonVariant::modified)
    throw InputError("Newton variant modified is not implemented yet: use full or one");
  if (s.solver == LinearSolverKind::cg && s.treatment != StiffnessTreatment::definite)
    throw InputError("linear solver cg needs a symmetric positive definite matrix: use the definite Jacobian "
                     "treatment with it, or linear solver ldlt, ldu or lu");
  if (s.solver == LinearSolverKind::ldlt && s.treatment == StiffnessTreatment::exact && scene.has_damping())
    throw InputError("linear solver ldlt needs a symmetric matrix, and the exact Jacobian of a damped cloth is "
                     "not: use linear solver ldu or lu, or the symmetric or definite Jacobian treatment");
}

ImplicitEuler::ImplicitEuler(ForceField& field, NewtonSettings settings)
    : Stepper(field), settings_(resolve(settings, field.scene())), A_(field.pattern()), cg_(field.dof_count()) {
  validate(settings_, field.scene());
  const int n = field.dof_count();
  v1_.resize(n), x1_.resize(n), f_.resize(n), r_.resize(n), dv_.resize(n);
  warm_dv_ = Vector::Zero(n);
  residuals_.reserve(static_cast<std::size_t>(max_iterations()) + 1);
  // The pattern never changes, so the fill-reducing ordering and the symbolic factorization are done once.
  if (settings_.solver == LinearSolverKind::ldlt) block_.analyze(A_, BlockLDU::Symmetry::symmetric);
  if (settings_.solver == LinearSolverKind::ldu) block_.analyze(A_, BlockLDU::Symmetry::general);
  if (settings_.solver == LinearSolverKind::lu) lu_.analyzePattern(A_);
}

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

bool ImplicitEuler::solve(const Vector& rhs, Vector& dv, bool warm_start) {
  using clock = std::chrono::steady_clock;
  linear_failure_.clear();
  linear_failure_kind_ = StepFailureKind::none;
  auto t0 = clock::now();
  switch (settings_.solver) {
    case LinearSolverKind::ldlt:
    case LinearSolverKind::ldu: {
      const bool factored = block_.factorize(A_);
      ++counters_.factorizations;
      timing_.factorization += seconds_since(t0);
      if (!factored) {
        linear_failure_kind_ = StepFailureKind::factorization_singular;
        linear_failure_ = "a pivot block is singular";
        return false;
      }
      t0 = clock::now();
      // Refined until the update is as accurate as the matrix allows; an update Newton cannot trust (the
      // factorization of an indefinite or non-symmetric J grew too much for refinement to recover) fails the
      // step rather than steering Newton with it.
      const double backward_error = block_.solve(A_, rhs, dv);
      if (!(backward_error <= max_backward_error)) {
        linear_failure_kind_ = StepFailureKind::refinement_failed;
        linear_failure_ = "backward error " + format_number(backward_error, 2) +
                          " after refinement (the pivoting lu solver may do better)";
        return false;
      }
      break;
    }
    case LinearSolverKind::lu:
      lu_.factorize(A_);
      ++counters_.factorizations;
      timing_.factorization += seconds_since(t0);
      if (lu_.info() != Eigen::Success) {
        linear_failure_kind_ = StepFailureKind::factorization_singular;
        linear_failure_ = "SparseLU could not factorize the matrix";
        return false;
      }
      t0 = clock::now();
      dv = lu_.solve(rhs);
      break;
    case LinearSolverKind::automatic: return false;  // never reached: resolve() ran in the constructor
    case LinearSolverKind::cg: {
      // The block-Jacobi preconditioner: each particle's 3x3 diagonal block inverted, O(n).
      if (!cg_.compute(A_)) {
        linear_failure_kind_ = StepFailureKind::factorization_singular;
        linear_failure_ = "a diagonal block of the preconditioner is singular";
        return false;
      }
      timing_.factorization += seconds_since(t0);
      t0 = clock::now();
      // The first update of a step resembles the previous step's, so it seeds CG; later updates start at 0.
      if (warm_start) dv = warm_dv_;
      else dv.setZero();
      const bool converged = cg_.solve(A_, rhs, dv, settings_.cg_tolerance, settings_.cg_max_iterations);
      counters_.cg_iterations += cg_.iterations();
      if (!converged) {
        linear_failure_kind_ = StepFailureKind::cg_not_converged;
        linear_failure_ = "CG did not converge in " + std::to_string(cg_.iterations()) + " iterations";
        return false;
      }
      break;
    }
  }
  ++counters_.linear_solves;
  timing_.solve += seconds_since(t0);
  if (!dv.allFinite()) {
    linear_failure_kind_ = StepFailureKind::newton_not_converged;
    linear_failure_ = "the update is not finite";
    return false;
  }
  return true;
}

double ImplicitEuler::residual_at(const Vector& x, const Vector& v, double h) {
  // r(v1) = M (v1 - v0) - h f(x0 + h v1, v1); r_ holds -r, the right-hand side of the Newton update.
  const double m = field_.scene().params().mass;
  x1_ = x + h * v1_;
  field_.forces(x1_, v1_, f_);
  ++counters_.rhs_evaluations;
  r_ = h * f_ - m * (v1_ - v);
  return r_.lpNorm<Eigen::Infinity>();
}

bool ImplicitEuler::step(double h, Vector& x, Vector& v) {
  using clock = std::chrono::steady_clock;
  const double m = field_.scene().params().mass;
  const double tol = settings_.tolerance;
  residuals_.clear();
  // [newton_loop]
  v1_ = v;  // the guess v1 = v0
  double residual = residual_at(x, v, h);
  residuals_.push_back(residual);
  double update = INFINITY;
  for (int k = 0;; ++k) {
    const double scale = 1.0 + v1_.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(residual)) break;
    if (residual <= tol * m * scale && (k == 0 || update <= tol * scale)) {
      v = v1_;
      x = x1_;
      counters_.newton_iterations += k;
      ++counters_.steps;
      return true;
    }
    if (k == max_iterations()) break;
    // Newton update: J dv = -r with J = M - h df/dv - h^2 df/dx at (x0 + h v1, v1).
    auto t0 = clock::now();
    field_.newton_matrix(x1_, v1_, h, settings_.treatment, A_);
    ++counters_.jacobian_assemblies;
    timing_.assembly += std::chrono::duration<double>(clock::now() - t0).count();
    if (!solve(r_, dv_, k == 0)) {
      failure_ = {linear_failure_kind_, std::string("linear solve (") + linear_solvers().name(settings_.solver) +
                                            ") failed in Newton iteration " + std::to_string(k + 1) +
                                            ", |r|_inf = " + format_number(residual, 3) + ": " + linear_failure_};
      counters_.newton_iterations += k + 1;
      return false;
    }
    if (k == 0) warm_dv_ = dv_;
    if (settings_.variant == NewtonVariant::one) {
      // Baraff & Witkin's linearly implicit step: one Newton iteration, accepted by design, unchecked.
      v1_ += dv_;
      x = x + h * v1_;
      v = v1_;
      counters_.newton_iterations += 1;
      ++counters_.steps;
      return true;
    }
    // Backtracking line search (Dennis & Schnabel 1996, 6.3): far from the solution, or when the matrix is
    // only an approximation of J (the symmetric and definite treatments), the full update can make the
    // residual grow; halving it until the residual decreases keeps Newton from wandering off. Close to the
    // solution the full step always decreases it, so quadratic convergence is untouched.
    double step_fraction = 1.0;
    v1_ += dv_;
    double trial = residual_at(x, v, h);
    while (!(trial < residual) && step_fraction > 1.0 / 64) {
      step_fraction *= 0.5;
      v1_ -= step_fraction * dv_;  // back from v1 + 2a dv to v1 + a dv
      trial = residual_at(x, v, h);
      ++counters_.line_search_halvings;
    }
    residual = trial;
    residuals_.push_back(residual);
    update = step_fraction * dv_.lpNorm<Eigen::Infinity>();
  }
  // [newton_loop]
  failure_ = {StepFailureKind::newton_not_converged,
              "Newton did not converge in " + std::to_string(max_iterations()) + " iterations: |r|_inf = " +
                  format_number(residuals_.back(), 3) + ", |dv|_inf = " + format_number(update, 3)};
  counters_.newton_iterations += max_iterations();
  return false;
}

}  // namespace cloth
