// The interface every time integrator implements: advance the free-particle state (x, v) by one step h,
// counting the work it did in machine-independent units.
#pragma once

#include "model/force_field.hpp"

#include <string>

namespace cloth {

/// Work done so far, in units that do not depend on the machine (Chapter 6 plots time against these).
struct StepCounters {
  long long steps = 0;
  long long rhs_evaluations = 0;      ///< evaluations of f(x, v)
  long long jacobian_assemblies = 0;  ///< Jacobians evaluated (K and D at a state): modified Newton forms several
                                      ///< Newton matrices from one (StageNewton)
  long long factorizations = 0;       ///< numeric sparse factorizations
  long long linear_solves = 0;
  long long cg_iterations = 0;        ///< conjugate-gradient iterations, summed over solves
  long long newton_iterations = 0;    ///< summed over steps
  long long line_search_halvings = 0; ///< Newton updates halved because the full one raised the residual or
                                      ///< did not decrease the incremental potential enough
  long long definite_fallbacks = 0;   ///< Newton iterations whose exact matrix was singular (a zero pivot), or,
                                      ///< minimising, whose exact update did not descend: solved again with the
                                      ///< definite matrix
  long long indefinite_factorizations = 0;  ///< LDL^T factorizations of an exact or symmetric Newton matrix
                                            ///< that was not positive definite (BlockLDU::positive_definite)
};

/// What stopped a step. run.txt's status names the kind (`step_failed newton_not_converged ...`, the model page's
/// table), so the names below are part of the programs' contract.
enum class StepFailureKind {
  none,                    ///< no failure
  newton_not_converged,    ///< Newton's residual did not fall below its tolerance within the iteration limit
  factorization_singular,  ///< a pivot of the direct factorization was singular
  cg_not_converged,        ///< conjugate gradients did not reach their tolerance
  refinement_failed,       ///< iterative refinement could not bring the backward error down
  line_search_exhausted,   ///< no damped Newton update lowered the incremental potential
  step_size_too_small,     ///< step control needed a step below its floor
};

/// The contract's name of a failure kind ("newton_not_converged", ...).
[[nodiscard]] constexpr const char* step_failure_name(StepFailureKind kind) {
  switch (kind) {
    case StepFailureKind::none: return "none";
    case StepFailureKind::newton_not_converged: return "newton_not_converged";
    case StepFailureKind::factorization_singular: return "factorization_singular";
    case StepFailureKind::cg_not_converged: return "cg_not_converged";
    case StepFailureKind::refinement_failed: return "refinement_failed";
    case StepFailureKind::line_search_exhausted: return "line_search_exhausted";
    case StepFailureKind::step_size_too_small: return "step_size_too_small";
  }
  return "unknown";
}

/// Why a step could not be taken: its kind and one line of detail.
struct StepFailure {
  StepFailureKind kind = StepFailureKind::none;
  std::string reason;  ///< one line: what failed, with iteration count and residual
};

/// A one-step method for x' = v, M v' = f(x, v) on a scene's free particles.
class Stepper {
 public:
  explicit Stepper(ForceField& field) : field_(field) {}
  virtual ~Stepper() = default;
  Stepper(const Stepper&) = delete;
  Stepper& operator=(const Stepper&) = delete;

  /// Short name used in run.txt and in plots ("explicit_euler", "rk4", "implicit_euler", ...).
  [[nodiscard]] virtual std::string name() const = 0;

  /// Advances (x, v) from t to t + h in place. Returns false, with x and v unchanged and failure() set,
  /// when the method could not take the step; a step is never accepted silently.
  virtual bool step(double h, Vector& x, Vector& v) = 0;

  [[nodiscard]] const StepCounters& counters() const { return counters_; }
  void reset_counters() { counters_ = {}; }
  [[nodiscard]] const StepFailure& failure() const { return failure_; }
  [[nodiscard]] ForceField& field() { return field_; }
  [[nodiscard]] const ForceField& field() const { return field_; }

 protected:
  ForceField& field_;
  StepCounters counters_;
  StepFailure failure_;
};

}  // namespace cloth
