// Newton's method for one implicit stage of the cloth (Chapters 4 and 9): given x~, v~ and gamma, find the stage
// velocity V with M (V - v~) = gamma f(x~ + gamma V, V). Implicit Euler, every stage of a diagonally implicit
// Runge-Kutta method and BDF2 are this one equation with different x~, v~ and gamma.
#pragma once

#include "base/name_table.hpp"
#include "integrators/block_ldu.hpp"
#include "integrators/pcg.hpp"
#include "integrators/stepper.hpp"

#include <Eigen/SparseLU>
#include <string>
#include <vector>

namespace cloth {

/// How each Newton system J dv = -r is solved.
enum class LinearSolverKind {
  ldlt,  ///< block LDL^T on the particles' 3x3 blocks (BlockLDU), ordering analysed once per scene: symmetric J
  ldu,   ///< block LDU, the same factorization for the exact, non-symmetric Jacobian of a damped cloth
  cg,    ///< conjugate gradients with a block-Jacobi (3x3) preconditioner, warm-started; needs the definite matrix
  lu,    ///< Eigen's sparse LU with partial pivoting: any matrix, slower; the reference the block solvers are
         ///< tested against
  automatic  ///< chosen for the matrix: ldu for the exact Jacobian of a damped cloth, ldlt otherwise
};
/// The solvers by name: ldlt, ldu, cg, lu, automatic.
const NameTable<LinearSolverKind>& linear_solvers();
const char* linear_solver_name(LinearSolverKind kind);

/// Which Newton iteration solves the stage equation.
enum class NewtonVariant {
  full,      ///< a fresh matrix at every iterate: quadratic convergence
  modified,  ///< one factorization kept across iterations, stages and steps while it still converges fast
  one        ///< Baraff & Witkin's linearly implicit step: one iteration from the guess, accepted as it is
};
/// The variants by name: full, modified, one.
const NameTable<NewtonVariant>& newton_variants();
const char* newton_variant_name(NewtonVariant variant);

/// What the iterated Newton variants (full, modified) solve and what their line search watches.
enum class LineSearch {
  /// The stage as the minimisation of the incremental potential Phi(V) (Martin et al. 2011; Gast et al. 2015),
  /// every damper frozen at the free-flight position x~ + gamma v~ so that damping has a dissipation potential;
  /// Armijo backtracking on Phi. The
  /// Newton matrix is Phi's Hessian: symmetric for every treatment, positive definite for `definite`.
  potential,
  /// The stage equation as it is (current damper directions), with backtracking on |r|_inf down to 1/64 of the
  /// update: the book's first Newton, which cannot take a frame step from a flat sheet.
  residual
};
/// The line searches by name: potential, residual.
const NameTable<LineSearch>& line_searches();

/// Newton's stopping rule and its linear algebra.
struct NewtonSettings {
  /// Converged when both |dv|_inf <= tol (1 + |V|_inf) and |r|_inf <= tol m (1 + |V|_inf), where
  /// r = M (V - v~) - gamma f(x~ + gamma V, V) is the residual after the update.
  double tolerance = 1e-8;
  /// Iterations before the stage is declared failed: a guard, not a criterion. Minimising, every iteration
  /// decreases Phi, but from a flat sheet at frame rate exact Newton needs about 20 before it turns quadratic,
  /// and the definite matrix converges only linearly (Chapter 4). 1 is Baraff & Witkin's linearly implicit
  /// step: one iteration from the guess, accepted as it is, by design (the same as NewtonVariant::one).
  int max_iterations = 100;
  LinearSolverKind solver = LinearSolverKind::automatic;
  /// exact (the default) makes Newton converge quadratically, damped or not; symmetric suits ldlt and lu;
  /// cg needs definite.
  StiffnessTreatment treatment = StiffnessTreatment::exact;
  double cg_tolerance = 1e-10;  ///< relative residual of each CG solve
  int cg_max_iterations = 2000;
  NewtonVariant variant = NewtonVariant::full;
  LineSearch line_search = LineSearch::potential;
  /// Stop on Hairer and Wanner's estimate of the iteration's remaining error instead of the two tests above:
  /// converged when theta / (1 - theta) |dv|_inf <= tol (1 + |V|_inf), theta the observed contraction
  /// |dv_k| / |dv_{k-1}| (from the previous solve for a first iteration), which for a fast contraction stops one
  /// iteration earlier (Hairer & Wanner 1996, IV.8). For the controlled runs of Chapter 9, whose tol is tied to
  /// the error tolerance.
  bool estimate_test = false;
  /// Modified Newton keeps the Jacobian (its stiffness and damping parts K and D) apart from the Newton matrix
  /// M - gamma D - gamma^2 K, so that a new gamma is first met by refactoring with the kept Jacobian, which is
  /// evaluated again only when that matrix fails to converge fast or has served steps_between_jacobians steps
  /// (SUNDIALS' rule, StageNewton). false evaluates both together at every refresh, the book's first rule.
  bool keep_jacobian = true;
  /// A diagonally implicit method starts each stage's Newton iteration from the previous step's dense output,
  /// the cubic Hermite interpolant of its velocities and accelerations, extrapolated to the stage's time; false
  /// starts it from the stage equation with the latest known force (DiagonallyImplicitRungeKutta). The
  /// one-iteration step never uses it: its single update defines the method from the step's own state.
  bool dense_output_predictor = true;

  /// Whether the iteration is the one-iteration step (variant one, or a limit of one iteration).
  [[nodiscard]] bool one_iteration() const { return variant == NewtonVariant::one || max_iterations == 1; }
  /// Whether Newton minimises the incremental potential. The one-iteration step never does: it takes its single
  /// update whole (a fraction of it would be an inconsistent step: half the update under gravity alone is half
  /// of gravity), so it has nothing to search and keeps the stage equation with the current dampers.
  [[nodiscard]] bool minimises() const { return line_search == LineSearch::potential && !one_iteration(); }
};

/// The settings with `automatic` replaced by the solver the matrix calls for: the exact Jacobian of a damped
/// cloth's stage equation is not symmetric, so it gets ldu; every other matrix (the other treatments, and every
/// Hessian of the incremental potential) is symmetric and gets ldlt.
NewtonSettings resolve(NewtonSettings settings, const Scene& scene);

/// Throws InputError when a setting is out of range or the solver cannot take the matrix the treatment gives (CG
/// needs the definite one, LDL^T a symmetric one). The message names the settings as the tables above name them;
/// a program maps them to its flags.
void validate(const NewtonSettings& settings, const Scene& scene);

/// Solves the stage equation r(V) = M (V - v~) - gamma f(x~ + gamma V, V) = 0 by Newton's method on the Newton
/// matrix J = M - gamma df/dv - gamma^2 df/dx, assembled in the pattern the ForceField analysed once. With the
/// potential line search (the default) the dampers are frozen at x~ + gamma v~ and r = grad Phi, where
///   Phi(V) = 1/2 (V - v~)^T M (V - v~) + E(x~ + gamma V) - E(x~) + gamma R(V),
/// E the spring and gravity energy and R the frozen dampers' dissipation potential; J is then Phi's Hessian.
/// The work is counted in the owning stepper's StepCounters.
class StageNewton {
 public:
  /// Modified Newton's reuse rule, with the defaults SUNDIALS documents for CVODE and ARKODE (Hindmarsh et al.,
  /// CVODE and ARKODE User Guides, "Nonlinear solver" and "Linear solver setup"): the Newton matrix is refactored
  /// when gamma has moved by more than max_gamma_change since its factorization (dgmax: 0.3 in CVODE, 0.2 in
  /// ARKODE), when steps_between_factorizations steps have passed and gamma has changed at all (msbp), or when
  /// the kept matrix contracts slower than slow_contraction (crdown); the Jacobian is evaluated again only when a
  /// matrix formed from the kept one fails that way, or after steps_between_jacobians steps (msbj, CVODE's 51).
  static constexpr double max_gamma_change = 0.2;
  static constexpr int steps_between_factorizations = 20;
  static constexpr int steps_between_jacobians = 51;
  /// The observed contraction |dv_k| / |dv_{k-1}| above which a kept matrix is declared stale. At 0.25 every
  /// iteration still gains more than half a digit; a slower chord iteration costs more force evaluations than a
  /// fresh factorization saves.
  static constexpr double slow_contraction = 0.25;

  StageNewton(ForceField& field, NewtonSettings settings, StepCounters& counters);

  /// Starts a new time step (modified Newton refreshes its matrix and its Jacobian after a number of steps).
  void begin_step() { ++steps_since_refresh_, ++jacobian_age_; }

  /// Solves the stage from the guess in V. On success V is the stage velocity, position() = x~ + gamma V and,
  /// when `need_force`, force() = f(position(), V). On failure returns false with failure() set; V is then
  /// meaningless.
  bool solve(const Vector& x_tilde, const Vector& v_tilde, double gamma, Vector& V, bool need_force);

  [[nodiscard]] const Vector& position() const { return x1_; }
  [[nodiscard]] const Vector& force() const { return f_; }
  [[nodiscard]] const StepFailure& failure() const { return failure_; }
  [[nodiscard]] const NewtonSettings& settings() const { return settings_; }
  /// |r|_inf at the start of each Newton iteration of the last solve, and after its last update.
  [[nodiscard]] const std::vector<double>& residual_history() const { return residuals_; }
  /// With the potential line search, Phi(V) at the same points as residual_history() (gravity's energy counted
  /// from x~, the spring energy whole), and the step fraction each update took; with the residual line search
  /// only the fractions.
  [[nodiscard]] const std::vector<double>& potential_history() const { return potentials_; }
  [[nodiscard]] const std::vector<double>& step_fractions() const { return fractions_; }
  /// |dv|_inf of each Newton update of the last solve, before its line search scaled it.
  [[nodiscard]] const std::vector<double>& update_history() const { return updates_; }
  /// Phi at V for the stage (x~, v~, gamma), with the dampers frozen at x~ + gamma v~ (Chapter 4's tests and
  /// page); not during a solve, whose frozen dampers it replaces.
  double potential(const Vector& x_tilde, const Vector& v_tilde, double gamma, const Vector& V);

  /// Seconds spent in assembly, factorization and solve since the last reset (for Chapter 6's breakdown).
  struct Timing {
    double assembly = 0, factorization = 0, solve = 0;
  };
  [[nodiscard]] const Timing& timing() const { return timing_; }
  void reset_timing() { timing_ = {}; }

 private:
  // Makes the Newton matrix J for gamma with `treatment` and factorizes it (or builds CG's preconditioner); false
  // on failure. With a kept Jacobian, J is formed from it unless `evaluate` asks for a new one at (x1_, V) (or the
  // kept one has another treatment); otherwise J is assembled at (x1_, V) directly.
  bool refresh(const Vector& V, double gamma, StiffnessTreatment treatment, bool evaluate);
  // Evaluates the Jacobian's two parts at (x1_, V), leaving J for gamma in A_.
  void evaluate_jacobian(const Vector& V, double gamma, StiffnessTreatment treatment);
  // Assembles J for gamma (any sign) at (x1_, V) into `A`.
  void assemble(const Vector& V, double gamma, StiffnessTreatment treatment, SparseMatrix& A);
  // dv = J^{-1} rhs with the matrix last refreshed.
  bool linear_solve(const Vector& rhs, Vector& dv, bool warm_start);
  // Sets x1_ = x~ + gamma V, f_ and r_ = -r(V), and returns |r|_inf; when minimising, also phi_ = Phi(V) and
  // phi_resolution_, the rounding bound of its evaluation.
  double residual_at(const Vector& x_tilde, const Vector& v_tilde, double gamma, const Vector& V, bool minimising);
  void fail_linear(int iteration, double residual);

  /// The block factorizations' updates are accepted up to this normwise backward error, a thousandth of
  /// Newton's default tolerance: an inexact update then never decides whether Newton converges.
  static constexpr double max_backward_error = 1e-11;

  ForceField& field_;
  NewtonSettings settings_;
  StepCounters& counters_;
  StepFailure failure_;
  StepFailureKind linear_failure_kind_ = StepFailureKind::none;
  std::string linear_failure_;  // why the last linear solve failed, for the failure reason
  SparseMatrix A_;
  BlockLDU block_;
  BlockJacobiPCG cg_;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  Vector x1_, f_, r_, dv_, warm_dv_;
  std::vector<double> residuals_, potentials_, fractions_, updates_;
  double phi_ = 0, phi_resolution_ = 0;
  Timing timing_;
  // Modified Newton: whether A_ holds a usable factorization, for which gamma, and how many steps ago.
  bool factored_ = false;
  double factored_gamma_ = 0;
  double contraction_ = 1;  // the last contraction rate observed, for the estimate test's first iteration
  int steps_since_refresh_ = 0;
  // The kept Jacobian, as the values of J(gamma) = M + gamma C1 + gamma^2 C2 in A_'s pattern: mass_ = M,
  // jacobian_v_ = C1 = -D (the damping part), jacobian_x_ = C2 = -K (the stiffness part); how many steps ago it
  // was evaluated and with which treatment. minus_ is the scratch matrix J(-gamma) of an evaluation.
  bool keeps_jacobian_ = false, has_jacobian_ = false;
  bool evaluated_ = false;  // whether the last refresh evaluated the Jacobian (at the iterate it factored)
  StiffnessTreatment jacobian_treatment_ = StiffnessTreatment::exact;
  int jacobian_age_ = 0;
  Vector mass_, jacobian_v_, jacobian_x_;
  SparseMatrix minus_;
};

}  // namespace cloth
