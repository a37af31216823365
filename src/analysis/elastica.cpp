// Shooting for the heavy elastica (the problem is stated in elastica.hpp and derived on the Chapter 12 page).
#include "analysis/elastica.hpp"

#include "base/input_error.hpp"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <string>

namespace cloth {

namespace {

// The state (theta, theta', x, y) along s, and its derivative.
using State = Eigen::Vector4d;

State derivative(double lambda, double s, const State& u) {
  return {u[1], -lambda * (1 - s) * std::cos(u[0]), std::cos(u[0]), std::sin(u[0])};
}

// Integrates from the clamp with theta'(0) = kappa0; records the shape when `shape` is given.
State shoot(double lambda, double kappa0, int steps, ElasticaShape* shape) {
  State u(0, kappa0, 0, 0);
  const double h = 1.0 / steps;
  if (shape != nullptr) {
    shape->x.assign(1, 0.0);
    shape->y.assign(1, 0.0);
  }
  for (int k = 0; k < steps; ++k) {
    const double s = k * h;
    const State k1 = derivative(lambda, s, u);
    const State k2 = derivative(lambda, s + h / 2, u + h / 2 * k1);
    const State k3 = derivative(lambda, s + h / 2, u + h / 2 * k2);
    const State k4 = derivative(lambda, s + h, u + h * k3);
    u += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    if (shape != nullptr) {
      shape->x.push_back(u[2]);
      shape->y.push_back(u[3]);
    }
  }
  return u;
}

}  // namespace

ElasticaShape heavy_elastica(double lambda, int steps) {
  if (!(std::isfinite(lambda) && lambda > 0 && lambda < 1e6))
    throw InputError("elastica: lambda = " + std::to_string(lambda) + ": expected a number in (0, 1e6)");
  if (steps < 10) throw InputError("elastica: expected at least 10 steps");
  // theta'(1) increases with theta'(0): more curvature at the clamp turns the strip further, which shortens the
  // arms of the weight beyond every point. It is < 0 at 0 and >= 0 at lambda / 2.
  double low = 0, high = lambda / 2;
  while (high - low > 4 * std::numeric_limits<double>::epsilon() * high) {
    const double mid = 0.5 * (low + high);
    if (shoot(lambda, mid, steps, nullptr)[1] < 0) low = mid;
    else high = mid;
  }
  ElasticaShape shape;
  shape.lambda = lambda;
  shape.clamp_curvature = 0.5 * (low + high);
  const State tip = shoot(lambda, shape.clamp_curvature, steps, &shape);
  shape.tip_x = tip[2];
  shape.tip_deflection = tip[3];
  shape.chord_angle = std::atan2(tip[3], tip[2]);
  return shape;
}

double small_deflection_tip(double lambda) { return lambda / 8; }

double peirce_lambda(double chord_angle) { return 8 * std::tan(chord_angle) / std::cos(chord_angle / 2); }

double elastica_lambda_for_chord(double chord_angle) {
  // The chord angle grows with lambda from 0 towards pi/2; Peirce's value is within a few percent, so a bracket
  // of a factor 4 around it holds the answer.
  double low = peirce_lambda(chord_angle) / 4, high = 4 * peirce_lambda(chord_angle);
  while (high - low > 1e-12 * high) {
    const double mid = 0.5 * (low + high);
    if (heavy_elastica(mid, 400).chord_angle < chord_angle) low = mid;
    else high = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace cloth
