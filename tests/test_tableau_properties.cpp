// What the book's method tables compute from a tableau agrees with theory: R(infinity), stiff accuracy, A- and
// L-stability and symplecticity of the implicit rows (Hairer & Wanner 1996, IV.3-IV.6; Hairer, Lubich & Wanner
// 2006, VI.4), the orders of the explicit rows and pairs, and the tables have one row per registry row.
#include "analysis/tableau_properties.hpp"
#include "integrators/method_registry.hpp"
#include "program/method_tables.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace cloth;

namespace {

TableauProperties of(const std::string& name) { return tableau_properties(*find_method(name).tableau); }

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("R(infinity): 0 for the L-stable rows, -1 for implicit midpoint and the trapezoidal rule") {
  // Backward Euler 1/(1 - z) -> 0; the Pade (1,1) approximant (1 + z/2)/(1 - z/2) -> -1; Alexander's SDIRKs
  // and TR-BDF2 are stiffly accurate with invertible (or, for TR-BDF2, invertible below its first row) A -> 0.
  CHECK(of("implicit_euler").r_infinity == doctest::Approx(0).epsilon(1e-9));
  CHECK(of("sdirk2").r_infinity == doctest::Approx(0).epsilon(1e-9));
  CHECK(of("sdirk3").r_infinity == doctest::Approx(0).epsilon(1e-9));
  CHECK(of("trbdf2").r_infinity == doctest::Approx(0).epsilon(1e-9));
  CHECK(of("implicit_midpoint").r_infinity == doctest::Approx(-1).epsilon(1e-9));
  CHECK(of("trapezoid").r_infinity == doctest::Approx(-1).epsilon(1e-9));
  CHECK(std::isinf(of("rk4").r_infinity));  // a polynomial R grows without bound
}

TEST_CASE("stiff accuracy, A- and L-stability and symplecticity of the implicit rows") {
  for (const char* name : {"implicit_euler", "sdirk2", "sdirk3", "trbdf2"}) {
    INFO(name);
    const TableauProperties p = of(name);
    CHECK(p.stiffly_accurate);
    CHECK(p.a_stable);
    CHECK(p.l_stable);
    CHECK_FALSE(p.symplectic);
  }
  // The trapezoidal rule's last row is its b, yet R(infinity) = -1: stiff accuracy gives L-stability only with
  // an invertible A, and its first (explicit) row makes A singular.
  CHECK(of("trapezoid").stiffly_accurate);
  CHECK(of("trapezoid").explicit_first_stage);
  CHECK(of("trapezoid").a_stable);
  CHECK_FALSE(of("trapezoid").l_stable);
  CHECK_FALSE(of("trapezoid").symplectic);
  // Implicit midpoint, the one-stage Gauss method: b_1 a_11 + b_1 a_11 = 1 = b_1 b_1, symplectic, not L-stable.
  CHECK_FALSE(of("implicit_midpoint").stiffly_accurate);
  CHECK(of("implicit_midpoint").a_stable);
  CHECK_FALSE(of("implicit_midpoint").l_stable);
  CHECK(of("implicit_midpoint").symplectic);
  CHECK_FALSE(of("implicit_midpoint").explicit_first_stage);
  // No explicit method is A-stable or symplectic (its R is a polynomial; b_i a_ii = 0 != b_i^2).
  for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta)) {
    INFO(m->name);
    const TableauProperties p = tableau_properties(*m->tableau);
    CHECK(p.explicit_method);
    CHECK_FALSE(p.a_stable);
    CHECK_FALSE(p.symplectic);
  }
}

TEST_CASE("the orders computed from the order conditions are the classical ones") {
  CHECK(of("explicit_euler").order == 1);
  CHECK(of("heun").order == 2);
  CHECK(of("midpoint").order == 2);
  CHECK(of("kutta3").order == 3);
  CHECK(of("rk4").order == 4);
  CHECK(of("rule38").order == 4);
  CHECK(of("sdirk3").order == 3);
  CHECK(of("trbdf2").order == 2);
  CHECK(of("trbdf2").embedded_order == 3);
  CHECK(of("dopri5").order == 5);
  CHECK(of("dopri5").embedded_order == 4);
  CHECK(of("rkf45").order == 4);
  CHECK(of("rkf45").embedded_order == 5);
  CHECK(of("rk4").stages == 4);
  CHECK(of("dopri5").stages == 7);
}

TEST_CASE("the book's method tables have one row per registry row of their families, with its description") {
  const std::string explicit_table = explicit_method_table().markdown();
  const std::string implicit_table = implicit_method_table().markdown();
  CHECK(count(explicit_table, "\n") == 2 + methods_of(MethodFamily::explicit_runge_kutta).size());
  CHECK(count(implicit_table, "\n") == 2 + newton_methods().size());
  for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta))
    CHECK(count(explicit_table, "| `" + m->name + "` |") == 1);
  for (const Method* m : newton_methods()) CHECK(count(implicit_table, "| `" + m->name + "` |") == 1);
  CHECK(count(implicit_table, "| `sdirk2` | 2 | 2 | yes | 0 | L-stable |") == 1);
  CHECK(count(implicit_table, "| `trapezoid` | 2 (explicit first) | 2 | yes | -1 | A-stable |") == 1);
  CHECK(count(implicit_table, "| `implicit_midpoint` | 1 | 2 | no | -1 | A-stable, symplectic |") == 1);
  CHECK(count(implicit_table, "| `trbdf2` | 3 (explicit first) | 2, embedded 3 | yes | 0 | L-stable |") == 1);
}
