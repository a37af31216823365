// Implicit (backward) Euler with Newton's method, Chapter 4: solve M (v1 - v0) = h f(x0 + h v1, v1) for v1 on
// the analytic sparse Jacobian J = M - h df/dv - h^2 df/dx, then x1 = x0 + h v1.
#pragma once

#include "base/name_table.hpp"
#include "integrators/block_ldu.hpp"
#include "integrators/pcg.hpp"
#include "integrators/stepper.hpp"

#include <Eigen/SparseLU>
#include <memory>
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

/// How Newton's method treats its matrix from one iteration to the next.
enum class NewtonVariant {
  full,      ///< J assembled and factored at every iterate: quadratic convergence
  modified,  ///< J assembled and factored once per step and reused: linear convergence, cheaper iterations
             ///< (named so that programs and messages know it; not implemented yet, refused by validate())
  one        ///< Baraff & Witkin's linearly implicit step: one iteration from v1 = v0, accepted as it is
};
/// The variants by name: full, modified, one.
const NameTable<NewtonVariant>& newton_variants();

/// Newton's stopping rule and its linear algebra.
struct NewtonSettings {
  /// Converged when both |dv|_inf <= tol (1 + |v1|_inf) and |r|_inf <= tol m (1 + |v1|_inf), where
  /// r = M (v1 - v0) - h f(x0 + h v1, v1) is the residual after the update.
  double tolerance = 1e-8;
  /// Iterations before the step is declared failed (full Newton; the one-step variant takes exactly one).
  int max_iterations = 20;
  LinearSolverKind solver = LinearSolverKind::automatic;
  /// exact (the default) makes Newton converge quadratically, damped or not; symmetric suits ldlt and lu;
  /// cg needs definite.
  StiffnessTreatment treatment = StiffnessTreatment::exact;
  double cg_tolerance = 1e-10;  ///< relative residual of each CG solve
  int cg_max_iterations = 2000;
  NewtonVariant variant = NewtonVariant::full;
};

/// The settings with `automatic` replaced by the solver the matrix calls for: the exact Jacobian of a damped
/// cloth is not symmetric, so it gets ldu; every other treatment gives a symmetric matrix, which gets ldlt.
NewtonSettings resolve(NewtonSettings settings, const Scene& scene);

/// Throws InputError when a setting is out of range, the variant is not implemented, or the solver cannot take
/// the matrix the treatment gives (CG needs the definite one, LDL^T a symmetric one). The message names the
/// settings as the tables above name them; a program maps them to its flags.
void validate(const NewtonSettings& settings, const Scene& scene);

class ImplicitEuler final : public Stepper {
 public:
  ImplicitEuler(ForceField& field, NewtonSettings settings);
  [[nodiscard]] std::string name() const override { return "implicit_euler"; }
  bool step(double h, Vector& x, Vector& v) override;

  [[nodiscard]] const NewtonSettings& settings() const { return settings_; }
  /// |r|_inf at the start of each Newton iteration of the last step, and after its last update.
  [[nodiscard]] const std::vector<double>& residual_history() const { return residuals_; }
  /// Seconds spent in the last step's assembly, factorization and solve (for Chapter 6's breakdown).
  struct Timing {
    double assembly = 0, factorization = 0, solve = 0;
  };
  [[nodiscard]] const Timing& timing() const { return timing_; }
  void reset_timing() { timing_ = {}; }

 private:
  bool solve(const Vector& rhs, Vector& dv, bool warm_start);
  // The iteration limit of a step: one for Baraff & Witkin's variant, the settings' limit otherwise.
  [[nodiscard]] int max_iterations() const {
    return settings_.variant == NewtonVariant::one ? 1 : settings_.max_iterations;
  }
  // Sets x1_ = x0 + h v1_, f_ and r_ = -r(v1_), and returns |r|_inf.
  double residual_at(const Vector& x, const Vector& v, double h);

  /// The block factorizations' updates are accepted up to this normwise backward error, a thousandth of
  /// Newton's default tolerance: an inexact update then never decides whether Newton converges.
  static constexpr double max_backward_error = 1e-11;

  NewtonSettings settings_;
  StepFailureKind linear_failure_kind_ = StepFailureKind::none;
  std::string linear_failure_;  // why the last linear solve failed, for the step's failure reason
  SparseMatrix A_;
  BlockLDU block_;
  BlockJacobiPCG cg_;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  Vector v1_, x1_, f_, r_, dv_, warm_dv_;
  std::vector<double> residuals_;
  Timing timing_;
};

}  // namespace cloth
