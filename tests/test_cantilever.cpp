// The cantilever strip against the heavy elastica (an independent solution of the continuum problem): the tip
// deflection of both bending models within 2 % at a spacing of L/20, a quarter of its error at L/10; the
// flexion-spring strip, with the stiffness Chapter 10 maps from B, misses it; the strip's weight is rho_A g W per
// length; the rest shape does not depend on where the search starts; at L/160 the search reaches rest, and the
// error is the O(d^2) quarter of L/80's plus the springs' stretch.
#include <doctest/doctest.h>

#include "analysis/cantilever.hpp"
#include "analysis/elastica.hpp"

#include <Eigen/Core>
#include <cmath>
#include <vector>

using namespace cloth;

namespace {

// The standard's strip at lambda = (L / c)^3 = 8: the overhang is twice the bending length, the tip chord near
// 41.5 degrees, a large deflection.
CantileverParams strip(BendingModel model, int cells) {
  CantileverParams p;
  p.model = model;
  p.overhang = 0.1;
  p.spacing = p.overhang / cells;
  p.areal_density = 0.2;
  p.bending_rigidity = p.areal_density * p.gravity * std::pow(p.overhang / 2, 3);
  return p;
}

double relative_tip_error(const CantileverParams& p, const CantileverRest& rest) {
  const double lambda = p.areal_density * p.gravity * std::pow(p.overhang, 3) / p.bending_rigidity;
  const ElasticaShape exact = heavy_elastica(lambda);
  return rest.tip_deflection / (exact.tip_deflection * p.overhang) - 1;
}

}  // namespace

TEST_CASE("the strip's particles carry its weight by area: rho_A g W per length, the clamp rows excluded") {
  Cantilever c(strip(BendingModel::hinge, 20));
  const CantileverParams& p = c.params();
  const double W = (c.scene().grid().N - 1) * p.spacing;
  CHECK(c.particle_masses().sum() == doctest::Approx(p.areal_density * W * (p.overhang - p.spacing / 2)).epsilon(1e-12));
  CHECK(c.scene().free_count() == (c.scene().grid().M - 2) * c.scene().grid().N);
}

TEST_CASE("both bending models hold the cantilever within 2 % of the elastica at L/20, four times closer than at L/10") {
  for (const BendingModel model : {BendingModel::hinge, BendingModel::quadratic}) {
    CAPTURE(bending_models().name(model));
    double previous = 0;
    for (const int cells : {10, 20}) {  // the error is O(d^2): a quarter at each halving
      CAPTURE(cells);
      Cantilever c(strip(model, cells));
      const CantileverRest rest = c.rest_shape();
      REQUIRE(rest.converged);
      const double error = relative_tip_error(c.params(), rest);
      MESSAGE(bending_models().name(model) << " L/" << cells << ": tip deflection " << rest.tip_deflection
                                           << " m, relative error " << error);
      if (cells == 20) CHECK(std::abs(error) < 0.02);
      if (previous != 0) CHECK(std::abs(error) < 0.35 * std::abs(previous));
      previous = error;
    }
  }
}

TEST_CASE("the flexion-spring strip, with the stiffness mapped from B at one curvature, misses the elastica") {
  Cantilever c(strip(BendingModel::flexion, 20));
  const CantileverRest rest = c.rest_shape();
  REQUIRE(rest.converged);
  const double error = relative_tip_error(c.params(), rest);
  MESSAGE("flexion L/20: relative error " << error);
  CHECK(error > 0.1);  // it droops further: its energy is quartic in the angle, too soft below kappa_ref
}

TEST_CASE("the rest shape does not depend on where the search starts: flat and along the elastica agree") {
  Cantilever c(strip(BendingModel::hinge, 10));
  const CantileverRest from_elastica = c.rest_shape(CantileverStart::elastica);
  const CantileverRest from_flat = c.rest_shape(CantileverStart::flat);
  REQUIRE(from_elastica.converged);
  REQUIRE(from_flat.converged);
  CHECK(from_flat.iterations > from_elastica.iterations);
  CHECK((from_flat.x - from_elastica.x).lpNorm<Eigen::Infinity>() <= 1e-9 * c.params().overhang);
}

TEST_CASE("at L/160 the hinge strip reaches rest above the forces' rounding and its tip error is a quarter of L/80's "
          "plus the springs' stretch" * doctest::test_suite("slow")) {
  // The search stops where the forces are as small as rounding lets them be: a coordinate of size L + W carries
  // eps (L + W), a spring's force K eps (L + W). At L/160 a particle weighs 7.7e-7 N and the search stalls near
  // 3e-13 N, 4e-7 weights: a floor taken from the spacing instead (64 eps K 2d = 1.8e-13 N) is never reached.
  std::vector<double> errors;
  for (const int cells : {80, 160}) {
    Cantilever c(strip(BendingModel::hinge, cells));
    const CantileverRest rest = c.rest_shape();
    REQUIRE(rest.converged);
    errors.push_back(relative_tip_error(c.params(), rest));
  }
  MESSAGE("hinge L/80, L/160: relative errors " << errors[0] << ", " << errors[1]);
  // O(d^2) takes a quarter; the sheet's stretch under its own weight, about rho_A g L / K = 2e-5 at the clamp,
  // adds a part that does not fall with d (5e-6 of the tip deflection, measured with springs 100 times stiffer).
  CHECK(errors[1] > 0.25 * errors[0]);
  CHECK(errors[1] < 0.25 * errors[0] + 1e-5);
}
