// Newton's method for one implicit stage, with the linear solver chosen for the matrix it gets and the three
// Newton variants of Chapter 9 (full, modified, one iteration).
#include "integrators/stage_newton.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace cloth {

const NameTable<LinearSolverKind>& linear_solvers() {
  static const NameTable<LinearSolverKind> table(
      "linear solver", {{LinearSolverKind::ldlt, "ldlt"}, {LinearSolverKind::ldu, "ldu"}, {LinearSolverKind::cg, "cg"},
                        {LinearSolverKind::lu, "lu"}, {LinearSolverKind::automatic, "automatic"}});
  return table;
}

const char* linear_solver_name(LinearSolverKind kind) { return linear_solvers().name(kind); }

const NameTable<NewtonVariant>& newton_variants() {
  static const NameTable<NewtonVariant> table(
      "Newton variant", {{NewtonVariant::full, "full"}, {NewtonVariant::modified, "modified"}, {NewtonVariant::one, "one"}});
  return table;
}

const char* newton_variant_name(NewtonVariant variant) { return newton_variants().name(variant); }

const NameTable<LineSearch>& line_searches() {
  static const NameTable<LineSearch> table("line search",
                                           {{LineSearch::potential, "potential"}, {LineSearch::residual, "residual"}});
  return table;
}

namespace {
// The exact Jacobian of a damped cloth's stage equation: the damper's d/dx has no transpose partner. The
// Hessian of the incremental potential, frozen dampers and all, is symmetric.
bool nonsymmetric(const NewtonSettings& settings, const Scene& scene) {
  return settings.treatment == StiffnessTreatment::exact && scene.has_damping() && !settings.minimises();
}
}  // namespace

NewtonSettings resolve(NewtonSettings settings, const Scene& scene) {
  if (settings.solver == LinearSolverKind::automatic)
    settings.solver = nonsymmetric(settings, scene) ? LinearSolverKind::ldu : LinearSolverKind::ldlt;
  return settings;
}

void validate(const NewtonSettings& settings, const Scene& scene) {
  const NewtonSettings s = resolve(settings, scene);
  if (!(s.tolerance > 0) || !std::isfinite(s.tolerance))
    throw InputError("Newton tolerance: expected a finite number > 0");
  if (s.max_iterations < 1) throw InputError("Newton iteration limit: expected a whole number >= 1");
  if (s.solver == LinearSolverKind::cg && s.treatment != StiffnessTreatment::definite)
    throw InputError("linear solver cg needs a symmetric positive definite matrix: use the definite Jacobian "
                     "treatment with it, or linear solver ldlt, ldu or lu");
  if (s.solver == LinearSolverKind::ldlt && nonsymmetric(s, scene))
    throw InputError("linear solver ldlt needs a symmetric matrix, and the exact Jacobian of a damped cloth is "
                     "not: use linear solver ldu or lu, or the symmetric or definite Jacobian treatment");
}

StageNewton::StageNewton(ForceField& field, NewtonSettings settings, StepCounters& counters)
    : field_(field), settings_(resolve(settings, field.scene())), counters_(counters), A_(field.pattern()),
      cg_(field.dof_count()) {
  validate(settings_, field.scene());
  const int n = field.dof_count();
  x1_.resize(n), f_.resize(n), r_.resize(n), dv_.resize(n);
  warm_dv_ = Vector::Zero(n);
  residuals_.reserve(static_cast<std::size_t>(settings_.max_iterations) + 2);
  potentials_.reserve(static_cast<std::size_t>(settings_.max_iterations) + 2);
  fractions_.reserve(static_cast<std::size_t>(settings_.max_iterations) + 2);
  updates_.reserve(static_cast<std::size_t>(settings_.max_iterations) + 2);
  // The pattern never changes, so the fill-reducing ordering and the symbolic factorization are done once.
  if (settings_.solver == LinearSolverKind::ldlt) block_.analyze(A_, BlockLDU::Symmetry::symmetric);
  if (settings_.solver == LinearSolverKind::ldu) block_.analyze(A_, BlockLDU::Symmetry::general);
  if (settings_.solver == LinearSolverKind::lu) lu_.analyzePattern(A_);
  // Modified Newton keeps its Jacobian in the pattern's value arrays, beside the mass diagonal M.
  keeps_jacobian_ = settings_.keep_jacobian && settings_.variant == NewtonVariant::modified &&
                    !settings_.one_iteration();
  if (keeps_jacobian_) {
    mass_ = Vector::Zero(A_.nonZeros());
    jacobian_v_ = mass_, jacobian_x_ = mass_;
    minus_ = A_;
    for (int k = 0; k < A_.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(A_, k); it; ++it)
        if (it.row() == k) mass_[&it.value() - A_.valuePtr()] = field.scene().params().mass;
  }
}

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The potential line search's smallest step fraction: a descending update decreases Phi long before this, so
// reaching it means the update does not descend (an indefinite matrix) or Phi is not finite along it.
constexpr double min_step_fraction = 0x1p-30;
}  // namespace

void StageNewton::assemble(const Vector& V, double gamma, StiffnessTreatment treatment, SparseMatrix& A) {
  if (settings_.minimises()) field_.frozen_newton_matrix(x1_, gamma, treatment, A);
  else field_.newton_matrix(x1_, V, gamma, treatment, A);
}

// [jacobian_parts]
void StageNewton::evaluate_jacobian(const Vector& V, double gamma, StiffnessTreatment treatment) {
  // J(gamma) = M + gamma C1 + gamma^2 C2 is a quadratic in gamma with the pattern's entries as coefficients, so
  // J(gamma) and J(-gamma) give both parts: C1 = (J(gamma) - J(-gamma)) / (2 gamma) is -D (df/dv, or the frozen
  // dampers' Hessian negated) and C2 = ((J(gamma) + J(-gamma)) / 2 - M) / gamma^2 is -K (df/dx, or the spring
  // Hessian negated, with the treatment applied). Taken at the gamma in use, the three terms are of the sizes
  // they have in the matrices formed from them, and A_ keeps J(gamma) as assembled.
  assemble(V, gamma, treatment, A_);
  assemble(V, -gamma, treatment, minus_);
  using Values = Eigen::Map<const Vector>;
  const Values plus(A_.valuePtr(), A_.nonZeros()), minus(minus_.valuePtr(), minus_.nonZeros());
  jacobian_v_ = (plus - minus) / (2 * gamma);
  jacobian_x_ = (0.5 * (plus + minus) - mass_) / (gamma * gamma);
  has_jacobian_ = true;
  jacobian_treatment_ = treatment;
  jacobian_age_ = 0;
}
// [jacobian_parts]

bool StageNewton::refresh(const Vector& V, double gamma, StiffnessTreatment treatment, bool evaluate) {
  using clock = std::chrono::steady_clock;
  linear_failure_.clear();
  linear_failure_kind_ = StepFailureKind::none;
  factored_ = false;
  auto t0 = clock::now();
  evaluated_ = !keeps_jacobian_ || evaluate || !has_jacobian_ || jacobian_treatment_ != treatment;
  if (!keeps_jacobian_) {
    assemble(V, gamma, treatment, A_);
    ++counters_.jacobian_assemblies;
  } else if (evaluated_) {
    evaluate_jacobian(V, gamma, treatment);
    ++counters_.jacobian_assemblies;
  } else {
    // The kept Jacobian with the new gamma: M - gamma D - gamma^2 K, no force pass.
    Eigen::Map<Vector>(A_.valuePtr(), A_.nonZeros()) = mass_ + gamma * jacobian_v_ + (gamma * gamma) * jacobian_x_;
  }
  timing_.assembly += seconds_since(t0);
  t0 = clock::now();
  const char* failure = nullptr;  // why the matrix could not be factored, if it could not
  switch (settings_.solver) {
    case LinearSolverKind::ldlt:
    case LinearSolverKind::ldu:
      ++counters_.factorizations;
      if (!block_.factorize(A_)) failure = "a pivot block is singular";
      // The exact Hessian of Phi is indefinite where compressed springs' negative transverse stiffness
      // outweighs the inertia M (Chapter 10 counts how often Newton meets it).
      else if (treatment != StiffnessTreatment::definite && settings_.solver == LinearSolverKind::ldlt &&
               !block_.positive_definite())
        ++counters_.indefinite_factorizations;
      break;
    case LinearSolverKind::lu:
      lu_.factorize(A_);
      ++counters_.factorizations;
      if (lu_.info() != Eigen::Success) failure = "SparseLU could not factorize the matrix";
      break;
    case LinearSolverKind::cg:
      // The block-Jacobi preconditioner: each particle's 3x3 diagonal block inverted, O(n).
      if (!cg_.compute(A_)) failure = "a diagonal block of the preconditioner is singular";
      break;
    case LinearSolverKind::automatic: return false;  // never reached: resolve() ran in the constructor
  }
  timing_.factorization += seconds_since(t0);
  if (failure != nullptr) {
    has_jacobian_ = false;  // a matrix formed from it cannot be factored: the next one starts afresh
    linear_failure_kind_ = StepFailureKind::factorization_singular;
    linear_failure_ = failure;
    return false;
  }
  factored_ = true;
  factored_gamma_ = gamma;
  steps_since_refresh_ = 0;
  return true;
}

bool StageNewton::linear_solve(const Vector& rhs, Vector& dv, bool warm_start) {
  using clock = std::chrono::steady_clock;
  linear_failure_.clear();
  linear_failure_kind_ = StepFailureKind::none;
  const auto t0 = clock::now();
  switch (settings_.solver) {
    case LinearSolverKind::ldlt:
    case LinearSolverKind::ldu: {
      // Refined until the update is as accurate as Newton needs it (a backward error of max_backward_error:
      // refining further costs a substitution and a product with J per step and changes no converged stage);
      // an update Newton cannot trust (the factorization of an indefinite or non-symmetric J grew too much for
      // refinement to recover) fails the step rather than steering Newton with it.
      const double backward_error = block_.solve(A_, rhs, dv, max_backward_error);
      if (!(backward_error <= max_backward_error)) {
        linear_failure_kind_ = StepFailureKind::refinement_failed;
        linear_failure_ = "backward error " + format_number(backward_error, 2) +
                          " after refinement (the pivoting lu solver may do better)";
        return false;
      }
      break;
    }
    case LinearSolverKind::lu: dv = lu_.solve(rhs); break;
    case LinearSolverKind::automatic: return false;  // never reached: resolve() ran in the constructor
    case LinearSolverKind::cg: {
      // The first update of a stage resembles the previous one's, so it seeds CG; later updates start at 0.
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

double StageNewton::residual_at(const Vector& x_tilde, const Vector& v_tilde, double gamma, const Vector& V,
                                bool minimising) {
  // r(V) = M (V - v~) - gamma f(x~ + gamma V, V); r_ holds -r, the right-hand side of the Newton update.
  const double m = field_.scene().params().mass;
  x1_ = x_tilde + gamma * V;
  ++counters_.rhs_evaluations;
  if (!minimising) {
    field_.forces(x1_, V, f_);
    r_ = gamma * f_ - m * (V - v_tilde);
    return r_.lpNorm<Eigen::Infinity>();
  }
  // [incremental_potential]
  // Phi(V) = 1/2 m |V - v~|^2 + E_spring(x~ + gamma V) + m g gamma sum V_z + gamma R(V): gravity's energy
  // counted from x~ (exactly, without the cancellation of two large sums), the spring energy and the frozen
  // dampers' dissipation potential R from the force pass itself.
  const ForceField::Potentials p = field_.frozen_forces(x1_, V, f_);
  r_ = gamma * f_ - m * (V - v_tilde);
  const double inertia = 0.5 * m * (V - v_tilde).squaredNorm();
  const int n = field_.scene().free_count();
  const double fall = m * field_.scene().params().gravity * gamma * V.reshaped(3, n).row(2).sum();
  phi_ = inertia + p.spring + fall + gamma * p.dissipation;
  // [incremental_potential]
  // A sum of k terms is exact to (k - 1) u sum |terms| (Higham 2002, 2.2): differences of Phi below this are
  // rounding, and cannot judge a step.
  const double magnitude = inertia + p.spring + std::abs(m * field_.scene().params().gravity * gamma) *
                                                    V.reshaped(3, n).row(2).cwiseAbs().sum() +
                           gamma * p.dissipation;
  phi_resolution_ = std::numeric_limits<double>::epsilon() * (p.terms + 3 * n + 4) * magnitude;
  return r_.lpNorm<Eigen::Infinity>();
}

double StageNewton::potential(const Vector& x_tilde, const Vector& v_tilde, double gamma, const Vector& V) {
  x1_ = x_tilde + gamma * v_tilde;
  field_.freeze_dampers(x1_);
  residual_at(x_tilde, v_tilde, gamma, V, true);
  return phi_;
}

void StageNewton::fail_linear(int iteration, double residual) {
  failure_ = {linear_failure_kind_, std::string("linear solve (") + linear_solver_name(settings_.solver) +
                                        ") failed in Newton iteration " + std::to_string(iteration) +
                                        ", |r|_inf = " + format_number(residual, 3) +
                                        (linear_failure_.empty() ? "" : ": " + linear_failure_)};
}

bool StageNewton::solve(const Vector& x_tilde, const Vector& v_tilde, double gamma, Vector& V, bool need_force) {
  const double m = field_.scene().params().mass;
  const double tol = settings_.tolerance;
  const bool modified = settings_.variant == NewtonVariant::modified && !settings_.one_iteration();
  const bool minimising = settings_.minimises();
  residuals_.clear();
  potentials_.clear();
  fractions_.clear();
  updates_.clear();
  // The dissipation potential's dampers are frozen for the whole solve: only then is damping a gradient, and Phi
  // a function to minimise. They point as at x~ + gamma v~, where the stage's particles would be if no force
  // acted during it: that position is O(h^2) from the stage's, so the frozen damper changes the stage by
  // O(h^3) and keeps the second order of sdirk2, BDF2 and the trapezoidal rule (taken at x~ itself, the start
  // of the step for implicit Euler, the change is O(h^2) and every method drops to first order on a damped
  // cloth). Free flight has no stiff term: it stays a sensible position at frame-rate steps.
  if (minimising) {
    x1_ = x_tilde + gamma * v_tilde;
    field_.freeze_dampers(x1_);
  }
  // [newton_loop]
  double residual = residual_at(x_tilde, v_tilde, gamma, V, minimising);
  residuals_.push_back(residual);
  if (minimising) potentials_.push_back(phi_);
  double update = INFINITY, previous_update = INFINITY;
  // [reuse_rule]
  // Modified Newton keeps the matrix it has unless it was never made, gamma moved beyond max_gamma_change, or it
  // is old and gamma has changed at all (with a kept Jacobian a refactor at the same gamma gives the same matrix).
  // A new matrix is formed from the kept Jacobian unless that has served steps_between_jacobians steps; otherwise
  // the Jacobian is evaluated afresh only below, when a matrix formed from it converges slowly or does not
  // descend.
  const bool gamma_moved = factored_ && std::abs(gamma / factored_gamma_ - 1) > max_gamma_change;
  const bool matrix_old = steps_since_refresh_ >= steps_between_factorizations &&
                          (!keeps_jacobian_ || gamma != factored_gamma_);
  const bool jacobian_old = keeps_jacobian_ && jacobian_age_ >= steps_between_jacobians;
  bool stale = !modified || !factored_ || gamma_moved || matrix_old || jacobian_old;
  bool evaluate = !keeps_jacobian_ || jacobian_old;
  // [reuse_rule]
  for (int k = 0;; ++k) {
    const double scale = 1.0 + V.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(residual)) break;
    if (residual <= tol * m * scale && (k == 0 || update <= tol * scale)) {
      counters_.newton_iterations += k;
      return true;
    }
    // Hairer and Wanner's test: with contraction theta the iterate is within theta / (1 - theta) |dv| of the
    // solution, so a fast contraction stops before |dv| itself is small. The first update of a solve uses the
    // rate of the one before.
    if (settings_.estimate_test && k > 0 && std::isfinite(residual)) {
      const double theta = k > 1 ? update / previous_update : std::pow(contraction_, 0.8);  // HW's caution
      if (k > 1) contraction_ = theta;
      if (theta < 1 && theta / (1 - theta) * update <= tol * scale) {
        counters_.newton_iterations += k;
        return true;
      }
    }
    if (k == settings_.max_iterations) break;
    // Newton update: J dv = -r with J = M - gamma df/dv - gamma^2 df/dx, at (x~ + gamma V, V) when fresh.
    // [singular_fallback]
    // An exact matrix can be singular, not only indefinite: M + gamma^2 H passes through a zero eigenvalue when
    // the Hessian H has negative curvature of size M / gamma^2 (compressed springs; hinges folded away from flat,
    // whose theta d^2 theta / dx^2 term is indefinite). LDL^T then meets a zero pivot. That iteration takes the
    // definite matrix, which has no negative part, and counts it beside the non-descending ones below.
    const auto refresh_or_definite = [&](bool evaluate_jacobian) {
      if (refresh(V, gamma, settings_.treatment, evaluate_jacobian)) return true;
      if (settings_.treatment == StiffnessTreatment::definite ||
          linear_failure_kind_ != StepFailureKind::factorization_singular)
        return false;
      ++counters_.definite_fallbacks;
      return refresh(V, gamma, StiffnessTreatment::definite, true);
    };
    // [singular_fallback]
    // `fresh`: this iteration's matrix is the Newton matrix at this iterate, not one kept or formed from a kept
    // Jacobian.
    bool fresh = stale;
    if (stale) {
      if (!refresh_or_definite(evaluate)) {
        fail_linear(k + 1, residual);
        counters_.newton_iterations += k + 1;
        return false;
      }
      fresh = evaluated_;
    }
    stale = !modified;
    bool solved = linear_solve(r_, dv_, k == 0);
    const auto descends = [&] { return solved && r_.dot(dv_) > 0; };
    // A kept matrix whose update does not descend is first replaced by a fresh one, with a new Jacobian.
    if (minimising && !fresh && !descends()) {
      if (!refresh_or_definite(true)) {
        fail_linear(k + 1, residual);
        counters_.newton_iterations += k + 1;
        return false;
      }
      solved = linear_solve(r_, dv_, false);
      fresh = true;
    }
    // [definite_fallback]
    // Minimising, an update that does not descend (r . dv <= 0, from an exact Hessian that is indefinite here)
    // cannot decrease Phi at any step length. That iteration takes the definite matrix instead, which is
    // positive definite and so always descends; full Newton's next iteration tries the exact one again, which
    // near a minimiser of Phi is positive definite and converges quadratically.
    if (minimising && settings_.treatment != StiffnessTreatment::definite && !descends()) {
      if (!refresh(V, gamma, StiffnessTreatment::definite, true)) {
        fail_linear(k + 1, residual);
        counters_.newton_iterations += k + 1;
        return false;
      }
      ++counters_.definite_fallbacks;
      solved = linear_solve(r_, dv_, false);
      fresh = true;  // modified Newton keeps the definite matrix while it serves: it always descends
    }
    // [definite_fallback]
    if (!solved) {
      fail_linear(k + 1, residual);
      counters_.newton_iterations += k + 1;
      return false;
    }
    if (k == 0) warm_dv_ = dv_;
    if (settings_.one_iteration()) {
      // Baraff & Witkin's linearly implicit step: one Newton iteration, accepted by design, unchecked.
      V += dv_;
      x1_ = x_tilde + gamma * V;
      counters_.newton_iterations += 1;
      if (need_force) {
        field_.forces(x1_, V, f_);
        ++counters_.rhs_evaluations;
      }
      return true;
    }
    const double phi = phi_, resolution = phi_resolution_;
    // grad Phi . dv = r . dv = -(r_ . dv): negative when dv descends, as it does whenever J is positive definite.
    const double slope = -r_.dot(dv_);
    V += dv_;
    double trial = residual_at(x_tilde, v_tilde, gamma, V, minimising);
    // Whether the step of fraction a is accepted: Armijo's sufficient decrease of Phi (Nocedal & Wright 2006,
    // 3.1, c1 = 1e-4); on the residual, any decrease of |r|_inf. Close to the solution the decrease Newton
    // predicts, -a r.dv, falls below the rounding of Phi's sums: Phi can no longer judge the step. A fresh
    // matrix's update is then taken whole (Newton's local convergence needs no search), a kept matrix's only
    // if the residual fell.
    const auto unresolved = [&](double a) { return -a * slope <= resolution + phi_resolution_; };
    const auto accepted = [&](double a) {
      if (!minimising) return trial < residual;
      if (unresolved(a)) return fresh || trial < residual;
      return phi_ <= phi + 1e-4 * a * slope;
    };
    if (!fresh && !accepted(1.0)) {
      // A kept matrix whose update was refused is too far from J: undo the update, refresh next time.
      V -= dv_;
      residual = residual_at(x_tilde, v_tilde, gamma, V, minimising);
      residuals_.push_back(residual);
      if (minimising) potentials_.push_back(phi_);
      fractions_.push_back(0.0);
      updates_.push_back(dv_.lpNorm<Eigen::Infinity>());
      stale = evaluate = true;
      continue;
    }
    double step_fraction = 1.0;
    if (minimising) {
      // [potential_line_search]
      // Backtracking on Phi: Newton's update minimises Phi's quadratic model, which far from the minimiser can
      // promise much more than Phi gives (from a flat sheet the model has no transverse spring stiffness at
      // all). With a positive definite J the update descends, so halving it ends with sufficient decrease.
      while (!accepted(step_fraction) && step_fraction > min_step_fraction) {
        step_fraction *= 0.5;
        V -= step_fraction * dv_;  // back from V + 2a dv to V + a dv
        trial = residual_at(x_tilde, v_tilde, gamma, V, minimising);
        ++counters_.line_search_halvings;
      }
      // [potential_line_search]
      if (!accepted(step_fraction)) {
        failure_ = {StepFailureKind::line_search_exhausted,
                    "Newton iteration " + std::to_string(k + 1) + ": no step down to 2^-30 of the update decreases "
                    "the incremental potential (|r|_inf = " + format_number(residual, 3) + ", slope r.dv = " +
                    format_number(-slope, 3) + ")"};
        counters_.newton_iterations += k + 1;
        return false;
      }
    } else {
      // Backtracking on the residual (Dennis & Schnabel 1996, 6.3): far from the solution, or when the matrix is
      // only an approximation of J (the symmetric and definite treatments), the full update can make the
      // residual grow; halving it until the residual decreases keeps Newton from wandering off. Close to the
      // solution the full step always decreases it, so quadratic convergence is untouched. |r|_inf is not a
      // function the update descends, so the search may find no decrease: it stops at 1/64 and keeps that step.
      while (!accepted(step_fraction) && step_fraction > 1.0 / 64) {
        step_fraction *= 0.5;
        V -= step_fraction * dv_;
        trial = residual_at(x_tilde, v_tilde, gamma, V, minimising);
        ++counters_.line_search_halvings;
      }
    }
    residual = trial;
    residuals_.push_back(residual);
    if (minimising) potentials_.push_back(phi_);
    fractions_.push_back(step_fraction);
    updates_.push_back(dv_.lpNorm<Eigen::Infinity>());
    previous_update = update;
    update = step_fraction * dv_.lpNorm<Eigen::Infinity>();
    // A kept matrix that contracts slowly costs more iterations than a new factorization (SUNDIALS' crdown), and
    // one formed from a kept Jacobian then needs a new Jacobian too.
    if (modified && !fresh && update > slow_contraction * previous_update) stale = evaluate = true;
  }
  // [newton_loop]
  failure_ = {StepFailureKind::newton_not_converged,
              "Newton did not converge in " + std::to_string(settings_.max_iterations) + " iterations: |r|_inf = " +
                  format_number(residuals_.back(), 3) + ", |dv|_inf = " + format_number(update, 3)};
  counters_.newton_iterations += settings_.max_iterations;
  return false;
}

}  // namespace cloth
