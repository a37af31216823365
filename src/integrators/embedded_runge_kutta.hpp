// The Runge-Kutta engine of Chapter 3 for an embedded pair: one attempt forms the stages once and from them both
// the new state (row b) and the estimate of its local error (rows b - b-hat), without touching the state, so that
// step control (step_control.hpp, adaptive_simulate.hpp) can accept the step or try again with a smaller one.
#pragma once

#include "integrators/butcher_tableau.hpp"
#include "integrators/stepper.hpp"

#include <vector>

namespace cloth {

/// For y = (x, v), y' = (v, a(x, v)) the stage derivative is k_i = (V_i, a_i), so the new state and the error
/// estimate are
///   x1 = x + h sum_i b_i V_i,               v1 = v + h sum_i b_i a_i,
///   e_x = h sum_i (b_i - bhat_i) V_i,        e_v = h sum_i (b_i - bhat_i) a_i.
/// The first stage is evaluated at (x, v) itself, so it is kept across a rejected attempt (the state has not
/// moved) and, for a first-same-as-last pair, taken from the accepted step's last stage: dopri5 costs six
/// evaluations per step, not seven. Every buffer is allocated by the constructor.
class EmbeddedRungeKutta final : public Stepper {
 public:
  /// `tableau` must pass validate() and carry an embedded row (throws InputError otherwise).
  EmbeddedRungeKutta(ForceField& field, ButcherTableau tableau);
  [[nodiscard]] std::string name() const override { return tableau_.name; }
  [[nodiscard]] const ButcherTableau& tableau() const { return tableau_; }
  /// The order of the error estimate, min(p, p-hat) + 1: the power of h the estimate scales with.
  [[nodiscard]] int estimate_order() const { return std::min(tableau_.order, tableau_.embedded_order) + 1; }

  /// Forms the stages of a step h from (x, v) and from them the candidate and the error estimate; (x, v) are not
  /// changed. (x, v) must be the state the last accept() left (or any state after restart()).
  void attempt(double h, const Vector& x, const Vector& v);
  [[nodiscard]] const Vector& candidate_x() const { return x_new_; }
  [[nodiscard]] const Vector& candidate_v() const { return v_new_; }
  [[nodiscard]] const Vector& error_x() const { return error_x_; }
  [[nodiscard]] const Vector& error_v() const { return error_v_; }

  /// The candidate of the last attempt becomes the state (an exchange of buffers, no copy); a first-same-as-last
  /// pair keeps its last stage as the next step's first.
  void accept(Vector& x, Vector& v);

  /// The acceleration a(x, v) at the state the next attempt starts from (its first stage), evaluated only when it
  /// is not already known.
  const Vector& first_stage(const Vector& x, const Vector& v);

  /// a = a(x, v), counted as one evaluation (for the first-step heuristic's probe).
  void evaluate(const Vector& x, const Vector& v, Vector& a) {
    field_.acceleration(x, v, a);
    ++counters_.rhs_evaluations;
  }

  /// Forget the first stage: the state was changed by someone else than accept().
  void restart() { first_known_ = false; }

  /// A fixed step without error control (restart, attempt, accept): the pair as an ordinary method of order p.
  bool step(double h, Vector& x, Vector& v) override;

 private:
  ButcherTableau tableau_;
  Eigen::VectorXd d_;             // b - b-hat
  bool fsal_ = false;
  bool first_known_ = false;      // stage_a_[0] holds a(x, v) of the current state
  std::vector<Vector> stage_v_;   // V_i, for the stages that have one of their own
  std::vector<const Vector*> V_;  // V_i itself: &stage_v_[i], &v_new_ (the last stage of a FSAL pair), or &v
  std::vector<Vector> stage_a_;   // a_i = M^{-1} f(X_i, V_i)
  std::vector<const Vector*> a_;  // &stage_a_[i] (an exchange of buffers keeps the objects where they are)
  Vector stage_x_;                // X_i, needed only while a_i is evaluated
  Vector x_new_, v_new_;          // the candidate; a FSAL pair's last stage is formed here directly
  Vector error_x_, error_v_;
};

}  // namespace cloth
