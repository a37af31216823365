// Any diagonally implicit Runge-Kutta method on the cloth (Chapter 9), given by its tableau: each stage is one
// stage equation solved by StageNewton, on the cloth's second-order structure (stage velocities as unknowns).
#pragma once

#include "integrators/implicit_tableaus.hpp"
#include "integrators/newton_stepper.hpp"

#include <string>
#include <vector>

namespace cloth {

/// One step of an s-stage DIRK method on x' = v, M v' = f(x, v). Stage i has velocity V_i and position
///   X_i = x~_i + h a_ii V_i,   x~_i = x0 + h sum_{j<i} a_ij V_j,
/// and its velocity solves M (V_i - v~_i) = h a_ii f(X_i, V_i), v~_i = v0 + h M^{-1} sum_{j<i} a_ij F_j, with
/// F_j = f(X_j, V_j): the implicit Euler equation of Chapter 4 with h a_ii for h, started from (x~_i, v~_i). The
/// step is x1 = x0 + h sum_i b_i V_i, v1 = v0 + h M^{-1} sum_i b_i F_i, or the last stage when the tableau is
/// stiffly accurate. Newton starts each stage from one of two guesses: the previous step's dense output, when the
/// step continues one (NewtonSettings::dense_output_predictor, a stiffly accurate tableau), which is the cubic
/// Hermite interpolant of that step's velocities and accelerations at its two ends extrapolated to the stage's
/// time t + c_i h; or V_i = v~_i + h a_ii M^{-1} F, F the latest stage force known (of this step, or the last one
/// of the step before): the stage equation with a known force in place of its own. The dense output is taken
/// while it was the closer of the two to the stages the last step solved.
class DiagonallyImplicitRungeKutta : public NewtonStepper {
 public:
  /// The tableau must pass validate(ImplicitTableau); the settings validate(NewtonSettings). Throws InputError.
  DiagonallyImplicitRungeKutta(ForceField& field, ImplicitTableau tableau, NewtonSettings settings);
  [[nodiscard]] std::string name() const override;
  bool step(double h, Vector& x, Vector& v) override;

  [[nodiscard]] const ImplicitTableau& tableau() const { return tableau_; }

  /// For an embedded pair, after a step: the difference between the step and its embedded companion, in
  /// positions and velocities (h sum_i (b_i - b^_i) V_i and h M^{-1} sum_i (b_i - b^_i) F_i).
  [[nodiscard]] const Vector& error_positions() const { return error_x_; }
  [[nodiscard]] const Vector& error_velocities() const { return error_v_; }

 private:
  ImplicitTableau tableau_;
  std::vector<Vector> V_, F_;   // stage velocities and forces
  std::vector<bool> need_force_;  // whether F_i is used (by a later stage or the weights)
  Vector x_tilde_, v_tilde_, error_x_, error_v_;
  // The predictor's force: the last stage force of the step before, when the step continues the state that step
  // produced (x_last_, v_last_); f(x1, v1) itself for a stiffly accurate method.
  Vector last_force_, x_last_, v_last_;
  bool have_last_force_ = false;
  // A finished step as its dense output: its length, the velocity and acceleration at its start (v0, a0) and end
  // (v1, a1), and its end position x1, by which a later step recognises that it continues this one.
  struct DenseOutput {
    Vector v0, a0, x1, v1, a1;
    double h = 0;
    bool valid = false;
  };
  // The last step finished and the one before it: a step rejected by the step control is retried from the end of
  // the one before, whose dense output then still serves.
  DenseOutput last_, before_;
  Vector v_start_;  // the step's starting velocity, kept for its dense output
  // Both guesses of a stage, and whether the dense output's was the closer to the solved stages of the last step
  // that had both: at long steps the cubic can be far off, and a guess far off can lead Newton to another
  // solution of the stage equation.
  Vector dense_guess_, force_guess_;
  bool dense_closer_ = true;
  // The predicted stage velocity at the time t0 + theta h_d of the step d (theta = 1 at its end).
  static void predict(const DenseOutput& d, double theta, Vector& V);
  // Keeps the finished step (length h, end state x, v) as the last dense output; `previous` is the one it
  // continued, if any.
  void record_dense_output(double h, const Vector& x, const Vector& v, const DenseOutput* previous);
};

}  // namespace cloth
