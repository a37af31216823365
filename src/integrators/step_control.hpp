// Step-size control for an embedded pair: the weighted error norm that turns an error estimate into one number
// measured in tolerances, the choice of the first step, and the controllers that pick the next step from it.
#pragma once

#include "integrators/embedded_runge_kutta.hpp"

namespace cloth {

/// How the 2n scaled components of an error estimate become one number.
enum class NormKind {
  rms,  ///< root mean square (Hairer, Norsett & Wanner): an error in one spring is diluted by the whole cloth
  max   ///< the largest component (as Boost.Odeint): an error in one spring counts in full
};

/// A component y_i of the state may err by atol + rtol |y_i| (Hairer, Norsett & Wanner 1993, II.4).
struct Tolerances {
  double rtol = 1e-6;
  double atol = 1e-6;
  NormKind norm = NormKind::rms;
};

/// Parses "rms" or "max"; throws InputError naming the accepted names.
NormKind norm_from_name(const std::string& name);
const char* norm_name(NormKind kind);

/// The error of a step in units of tolerance, with sc_i = atol + rtol max(|y0_i|, |y1_i|) over all 2n components
/// of (x, v):  err = sqrt( 1/(2n) sum_i (e_i / sc_i)^2 )  (HNW (4.11)), or err = max_i |e_i| / sc_i.
/// A step is acceptable when err <= 1. A non-finite estimate gives +infinity (the step is rejected).
double error_norm(const Vector& e_x, const Vector& e_v, const Vector& x0, const Vector& v0, const Vector& x1,
                  const Vector& v1, const Tolerances& tol);

/// The starting step of Hairer, Norsett & Wanner (1993), II.4: from the sizes of y0 and f(y0) a first guess h0,
/// then from one Euler step of h0 an estimate of the second derivative, and h such that the error of a step of
/// order k - 1 would be about 0.01 tolerances:
///   d0 = ||y0||, d1 = ||f0||, h0 = 0.01 d0 / d1,  d2 = ||f(y0 + h0 f0) - f0|| / h0,
///   h = min(100 h0, (0.01 / max(d1, d2))^(1/k))   (norms weighted as in error_norm with y1 = y0).
/// Costs two evaluations, one of which is the first step's first stage.
double initial_step(EmbeddedRungeKutta& rk, const Vector& x, const Vector& v, const Tolerances& tol);

enum class ControllerKind {
  elementary,  ///< h_new = h * safety * err^(-1/k) = h (rho/err)^(1/k)
  pi           ///< h_new = h (rho/err)^(0.3/k) (err_prev/err)^(0.4/k), rho = safety^k  (Gustafsson 1991; Soderlind 2002)
};

/// Parses "elementary" or "pi"; throws InputError naming the accepted names.
ControllerKind controller_from_name(const std::string& name);
const char* controller_name(ControllerKind kind);

/// Picks the factor by which the next step grows or shrinks, from the error of the step just attempted. The
/// elementary controller asks for err = 1 on the next step as if the error constant would not change; the PI
/// controller also looks at the previous accepted error, which damps the oscillation between accepted and
/// rejected steps that the elementary one shows when stability rather than accuracy limits the step
/// (Gustafsson 1991; Hairer & Wanner 1996, IV.2). k is the order of the estimate (min(p, p-hat) + 1).
class StepController {
 public:
  StepController(ControllerKind kind, int k, double safety = 0.9, double min_factor = 0.2, double max_factor = 10);

  /// The factor for the next step after an attempt with error `err`. After a rejection the step never grows.
  double factor(double err, bool accepted);
  [[nodiscard]] ControllerKind kind() const { return kind_; }

 private:
  ControllerKind kind_;
  double k_, safety_, min_factor_, max_factor_;
  double previous_error_;  // err of the last accepted step (rho before the first)
  bool after_rejection_ = false;
};

}  // namespace cloth
