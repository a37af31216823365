// The Butcher tableau: the built-ins have exactly the order they claim, the report's table read from its file is
// RK4, and the validator refuses every kind of bad tableau with a message naming the row or condition.
#include "base/input_error.hpp"
#include "integrators/butcher_tableau.hpp"
#include "integrators/method_registry.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace cloth;

namespace {

// The message parse_tableau throws for `text`, or "" when it accepts it.
std::string rejection(const std::string& text) {
  try {
    parse_tableau(text, "t.tableau");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("every built-in tableau passes validation and has no order beyond the one it claims") {
  for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta)) {
    const ButcherTableau& t = *m->tableau;
    INFO(t.name);
    CHECK_NOTHROW(validate(t));
    for (int p = 1; p <= t.order; ++p) CHECK(order_condition_defect(t, p) < 1e-15);
    CHECK(order_condition_defect(t, t.order + 1) > 1e-3);
  }
}

TEST_CASE("the report's table in chapters/03_runge_kutta/rk4_report.tableau is the built-in rk4") {
  const ButcherTableau file = read_tableau(std::string(CLOTH_SOURCE_DIR) + "/chapters/03_runge_kutta/rk4_report.tableau");
  const ButcherTableau rk4 = tableau_from_argument("rk4");
  CHECK(file.name == "rk4_report");
  CHECK(file.order == 4);
  CHECK((file.A - rk4.A).cwiseAbs().maxCoeff() == 0.0);
  CHECK((file.b - rk4.b).cwiseAbs().maxCoeff() == 0.0);
  CHECK((file.c - rk4.c).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("the tableau reader and validator reject each kind of bad tableau, naming the row or condition") {
  // a correct two-stage tableau to start from
  CHECK(rejection("name heun\norder 2\n0 0 0\n1 1 0\nb 1/2 1/2\n").empty());

  CHECK(contains(rejection(""), "empty tableau"));
  CHECK(contains(rejection("# only a comment\n"), "empty tableau"));
  // ragged: the second stage row has one entry too few; the message names the row and its line
  const std::string ragged = rejection("order 2\n0 0 0\n1 1\nb 1/2 1/2\n");
  CHECK(contains(ragged, "t.tableau:3:"));
  CHECK(contains(ragged, "stage row 2 has 2 numbers: expected 3"));
  CHECK(contains(rejection("order 2\n0 0 0\nb 1/2 1/2\n"), "1 stage rows but 2 weights"));
  // not a number
  const std::string word = rejection("order 2\n0 0 0\n1 one 0\nb 1/2 1/2\n");
  CHECK(contains(word, "t.tableau:3:"));
  CHECK(contains(word, "'one' is not a number"));
  CHECK(contains(rejection("order 2\n0 0 0\n1 1/0 0\nb 1/2 1/2\n"), "'1/0' is not a number"));
  // implicit: a_22 on the diagonal
  const std::string implicit = rejection("order 2\n0 0 0\n1 1/2 1/2\nb 1/2 1/2\n");
  CHECK(contains(implicit, "a_22 = 0.5 is on or above the diagonal"));
  CHECK(contains(implicit, "implicit"));
  // c inconsistent with A
  CHECK(contains(rejection("order 2\n0 0 0\n1/2 1 0\nb 1/2 1/2\n"), "row 2: c_2 = 0.5 but the row sum of A is 1"));
  // b not summing to 1
  CHECK(contains(rejection("order 1\n0 0 0\n1 1 0\nb 1/2 1/4\n"), "order-1 condition sum b_i = 1 (tree t) fails"));
  // a failed order condition: Heun's tableau claiming order 3
  CHECK(contains(rejection("order 3\n0 0 0\n1 1 0\nb 1/2 1/2\n"), "claims order 3 but the order-3 condition"));
  // no order, no b, an order out of range, rows after b
  CHECK(contains(rejection("0 0 0\n1 1 0\nb 1/2 1/2\n"), "no 'order' line"));
  CHECK(contains(rejection("order 2\n0 0 0\n1 1 0\n"), "no 'b' row"));
  CHECK(contains(rejection("order 9\n0 0\nb 1\n"), "'order' needs a whole number from 1 to 8"));
  CHECK(contains(rejection("order 1\n0 0\nb 1\n1 1\n"), "nothing but the weight rows 'b' and 'bhat' may follow"));
}

TEST_CASE("--tableau takes a built-in name or a readable file, and says which names exist") {
  CHECK(tableau_from_argument("rule38").order == 4);
  try {
    tableau_from_argument("rk5");
    FAIL("rk5 was accepted");
  } catch (const InputError& e) {
    CHECK(contains(e.what(), "explicit_euler, heun, midpoint, kutta3, rk4, rule38"));
  }
  try {
    tableau_from_argument("implicit_euler");  // registered, but not a tableau the explicit engine runs
    FAIL("implicit_euler was accepted as an explicit tableau");
  } catch (const InputError& e) {
    CHECK(contains(e.what(), "'implicit_euler'"));
  }
}
