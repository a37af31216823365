// The error norm, the first step and the two controllers of Chapter 8.
#include "integrators/step_control.hpp"

#include "base/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cloth {

double error_norm(const Vector& e_x, const Vector& e_v, const Vector& x0, const Vector& v0, const Vector& x1,
                  const Vector& v1, const Tolerances& tol) {
  // [error_norm]
  const auto scaled = [&](const Vector& e, const Vector& y0, const Vector& y1) {
    return e.array() / (tol.atol + tol.rtol * y0.array().abs().max(y1.array().abs()));
  };
  double err = 0;
  if (tol.norm == NormKind::rms) {
    const double sum = scaled(e_x, x0, x1).square().sum() + scaled(e_v, v0, v1).square().sum();
    err = std::sqrt(sum / static_cast<double>(e_x.size() + e_v.size()));
  } else {
    err = std::max(scaled(e_x, x0, x1).abs().maxCoeff(), scaled(e_v, v0, v1).abs().maxCoeff());
  }
  // [error_norm]
  return std::isfinite(err) ? err : std::numeric_limits<double>::infinity();
}

double initial_step(EmbeddedRungeKutta& rk, const Vector& x, const Vector& v, const Tolerances& tol) {
  // [initial_step]
  const Vector& a0 = rk.first_stage(x, v);  // f0 = (v, a0); the first step reuses it
  const auto norm = [&](const Vector& px, const Vector& pv) {
    return error_norm(px, pv, x, v, x, v, tol);
  };
  const double d0 = norm(x, v);
  const double d1 = norm(v, a0);
  const double h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : 0.01 * d0 / d1;
  // One explicit Euler step of h0: y1 = y0 + h0 f0, f1 = (v1, a(x1, v1)).
  const Vector x1 = x + h0 * v, v1 = v + h0 * a0;
  Vector a1(x.size());
  rk.evaluate(x1, v1, a1);
  const double d2 = norm(v1 - v, a1 - a0) / h0;
  const double k = rk.estimate_order();
  const double d = std::max(d1, d2);
  const double h1 = d <= 1e-15 ? std::max(1e-6, 1e-3 * h0) : std::pow(0.01 / d, 1.0 / k);
  // [initial_step]
  const double h = std::min(100 * h0, h1);
  return std::isfinite(h) && h > 0 ? h : 1e-6;  // tolerances so small that the norms overflow: start small
}

NormKind norm_from_name(const std::string& name) {
  if (name == "rms") return NormKind::rms;
  if (name == "max") return NormKind::max;
  throw InputError("'" + name + "' is not an error norm: expected rms or max");
}

const char* norm_name(NormKind kind) { return kind == NormKind::max ? "max" : "rms"; }

ControllerKind controller_from_name(const std::string& name) {
  if (name == "elementary") return ControllerKind::elementary;
  if (name == "pi") return ControllerKind::pi;
  throw InputError("'" + name + "' is not a controller: expected elementary or pi");
}

const char* controller_name(ControllerKind kind) { return kind == ControllerKind::pi ? "pi" : "elementary"; }

StepController::StepController(ControllerKind kind, int k, double safety, double min_factor, double max_factor)
    : kind_(kind),
      k_(k),
      safety_(safety),
      min_factor_(min_factor),
      max_factor_(max_factor),
      previous_error_(std::pow(safety, k)) {}

double StepController::factor(double err, bool accepted) {
  // [controller]
  // Both controllers aim at the same error per step, rho = safety^k (0.9^5 = 0.59 for dopri5): the elementary one
  // as HNW write it, h * safety * err^(-1/k) = h (rho / err)^(1/k); the PI one as Gustafsson (1991) writes it,
  //   h (rho / err_n)^(k_I) (err_{n-1} / err_n)^(k_P),   k_I = 0.3 / k, k_P = 0.4 / k,
  // whose proportional term answers how the error is changing, not only where it is.
  err = std::max(err, 1e-10);  // an estimate of zero would ask for an infinite step
  const double rho = std::pow(safety_, k_);
  double f = std::pow(rho / err, 1.0 / k_);
  if (accepted && kind_ == ControllerKind::pi && !after_rejection_)
    f = std::pow(rho / err, 0.3 / k_) * std::pow(previous_error_ / err, 0.4 / k_);
  f = std::clamp(f, min_factor_, after_rejection_ || !accepted ? 1.0 : max_factor_);
  // [controller]
  if (accepted) previous_error_ = err;
  after_rejection_ = !accepted;
  return f;
}

}  // namespace cloth
