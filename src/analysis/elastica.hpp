// The heavy elastica (Chapter 12's independent reference): the shape of an inextensible strip clamped level at one
// end and bent by its own weight, from the boundary-value problem for its angle, solved by shooting.
#pragma once

#include <vector>

namespace cloth {

/// A clamped heavy strip in units of its overhang L. theta(s) is the angle of the strip below the horizontal at
/// arc length s in [0, 1]; the moment balance B W theta' = q (the weight per length) times the arm of the strip
/// beyond s gives, after one derivative,
///   theta'' = -lambda (1 - s) cos theta,   theta(0) = 0 (clamped level),   theta'(1) = 0 (free end),
/// with the one parameter lambda = q L^3 / (B W) = (L / c)^3, c = (B / (rho_A g))^(1/3) the bending length.
struct ElasticaShape {
  double lambda = 0;
  double clamp_curvature = 0;  ///< theta'(0): the curvature at the clamp times L
  std::vector<double> x, y;    ///< the shape at s = k / n, k = 0..n: along the clamp's direction and downward
  double tip_x = 0;            ///< the tip's horizontal distance from the clamp, / L
  double tip_deflection = 0;   ///< how far the tip is below the clamp, / L
  double chord_angle = 0;      ///< the angle of the chord from the clamp to the tip below the horizontal [rad]
};

/// Solves the problem above for lambda > 0 by shooting on theta'(0): classical Runge-Kutta over `steps` equal
/// steps in s, bisection until theta'(1) = 0 to rounding. theta'(0) lies in (0, lambda / 2]: lambda / 2 is the
/// small-deflection value, and cos theta < 1 only lowers the moment.
ElasticaShape heavy_elastica(double lambda, int steps = 2000);

/// The small-deflection tip deflection / L of the same strip: w = q L^4 / (8 B W), so lambda / 8.
double small_deflection_tip(double lambda);

/// Peirce's (1930) approximation for the cantilever: (c / L)^3 = cos(phi / 2) / (8 tan phi) for a tip chord at
/// phi below the horizontal, returned as lambda = (L / c)^3. The ASTM D1388 reading takes phi = 41.5 degrees,
/// where (c / L)^3 = 1 / 8 nearly: the bending length is half the overhang.
double peirce_lambda(double chord_angle);

/// The lambda at which the elastica's tip chord is at `chord_angle` below the horizontal, by bisection: the exact
/// counterpart of peirce_lambda.
double elastica_lambda_for_chord(double chord_angle);

}  // namespace cloth
