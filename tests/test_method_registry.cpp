// The method registry keeps its promises: every row's tableau has the order the row claims, every closed-form
// stability function is the one its tableau gives, unknown names are refused with the list of accepted ones, and
// every settings table names each value once and parses its own names back.
#include "analysis/stability_function.hpp"
#include "base/input_error.hpp"
#include "integrators/method_registry.hpp"

#include <doctest/doctest.h>

#include <set>
#include <string>

using namespace cloth;

namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// The message `f` throws as InputError, or "" when it throws nothing.
template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Points of the left half plane and around it where the stability functions are compared.
const Complex sample_points[] = {{-0.5, 0},  {-2, 0},  {0, 1},   {0, -2.5}, {-1, 1.5},
                                 {-3, -0.5}, {0.3, 0.2}, {-10, 4}, {1e-3, 0}, {-0.1, 2.8}};

}  // namespace

TEST_CASE("every row is complete, its name is unique, and its tableau carries its name and order") {
  std::set<std::string> names;
  for (const Method& m : methods()) {
    INFO(m.name);
    CHECK(names.insert(m.name).second);
    CHECK(!m.title.empty());
    CHECK(!m.description.empty());  // the book's method tables print it
    CHECK(static_cast<bool>(m.make));
    CHECK(m.order >= 1);
    CHECK(std::string(method_families().name(m.family)) != "?");
    if (m.tableau) {
      CHECK(m.tableau->name == m.name);
      CHECK(m.tableau->order == m.order);
    }
    // the explicit Runge-Kutta family is exactly what the explicit engine runs
    if (m.family == MethodFamily::explicit_runge_kutta) {
      REQUIRE(m.tableau);
      CHECK_NOTHROW(validate(*m.tableau));
      CHECK_FALSE(m.tableau->has_embedded());
    }
    // an embedded pair is an explicit tableau with a second weight row whose order it states (Chapter 8)
    if (m.family == MethodFamily::embedded_runge_kutta) {
      REQUIRE(m.tableau);
      CHECK_NOTHROW(validate(*m.tableau));
      CHECK(m.tableau->has_embedded());
      CHECK(m.tableau->embedded_order >= 1);
      CHECK(m.tableau->embedded_order != m.order);
    }
    // a stepper comes out named as the row (the constrained rows refuse a sheet hung by its corners)
    SceneParams p;
    if (m.family == MethodFamily::constrained) p.pins = PinSet::edge;
    const Scene scene{p};
    ForceField field(scene);
    CHECK(m.stepper(field)->name() == m.name);
  }
  CHECK(method_names().size() == methods().size());
}

TEST_CASE("every registered tableau satisfies the order conditions of the order it claims, and no higher one") {
  int checked = 0;
  for (const Method& m : methods()) {
    if (!m.tableau) continue;
    INFO(m.name);
    // Tableaus given as fractions hold their conditions to a few ulps; Tsitouras published his as 16-digit
    // decimals, which hold them to about 1e-14, and ESDIRK3(2)4L[2]SA's embedded weights are 17-digit decimals.
    const double rounding = m.name == "tsit5" || m.name == "esdirk32" ? 1e-13 : 1e-15;
    for (int p = 1; p <= m.order; ++p) CHECK(order_condition_defect(*m.tableau, p) < rounding);
    if (m.order < 4) CHECK(order_condition_defect(*m.tableau, m.order + 1) > 1e-3);
    if (m.tableau->has_embedded())
      for (int p = 1; p <= m.tableau->embedded_order; ++p) CHECK(order_condition_defect(*m.tableau, p, true) < rounding);
    ++checked;
  }
  CHECK(checked >= 13);  // the six explicit tableaus, the six embedded pairs and implicit Euler's
}

TEST_CASE("each closed-form stability function is the R(z) = 1 + z b^T (I - z A)^-1 1 of its tableau") {
  for (const Method& m : methods()) {
    if (!m.stability) continue;
    INFO(m.name);
    REQUIRE(m.tableau);
    for (const Complex z : sample_points) {
      const Complex from_tableau = stability_function(*m.tableau, z);
      CHECK(std::abs(m.stability(z) - from_tableau) <= 1e-13 * std::max(1.0, std::abs(from_tableau)));
    }
  }
  // and the closed forms are the textbook ones
  for (const Complex z : sample_points) {
    CHECK(std::abs(find_method("explicit_euler").stability(z) - (1.0 + z)) < 1e-15 * (1 + std::abs(z)));
    const Complex rk4 = 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
    CHECK(std::abs(find_method("rk4").stability(z) - rk4) < 1e-13 * std::max(1.0, std::abs(rk4)));
    CHECK(std::abs(find_method("implicit_euler").stability(z) - 1.0 / (1.0 - z)) < 1e-15);
  }
  // symplectic Euler has none: on a mode it acts as a 2 x 2 matrix, not as a scalar R(z)
  CHECK_FALSE(static_cast<bool>(find_method("symplectic_euler").stability));
  CHECK(find_method("symplectic_euler").family == MethodFamily::partitioned);
}

TEST_CASE("an unknown method name is refused with the list of accepted names") {
  const std::string why = refusal([] { (void)find_method("rk5"); });
  CHECK(contains(why, "unknown method 'rk5'"));
  for (const Method& m : methods()) CHECK(contains(why, m.name));
  // the names that are no longer methods: the one-stage tableau has one name, Newton's variants are settings
  CHECK(contains(refusal([] { (void)find_method("euler"); }), "explicit_euler"));
  CHECK(contains(refusal([] { (void)find_method("implicit_euler_1newton"); }), "unknown method"));
  // an adaptive program's --tableau takes the embedded pairs by name and lists exactly them
  const std::string pairs_only = refusal([] { (void)embedded_tableau_from_argument("rk4"); });
  CHECK(contains(pairs_only, "'rk4' is neither a built-in embedded pair"));
  for (const Method* m : methods_of(MethodFamily::embedded_runge_kutta)) {
    CHECK(contains(pairs_only, m->name));
    CHECK(embedded_tableau_from_argument(m->name).name == m->name);
  }
  CHECK_FALSE(contains(pairs_only, "rule38"));
}

TEST_CASE("the Newton variant is a setting of implicit Euler: one takes a single unchecked iteration") {
  const Scene scene{SceneParams{}};
  ForceField field(scene);
  MethodSettings one;
  one.newton.variant = NewtonVariant::one;
  const auto stepper = make_stepper("implicit_euler", field, one);
  CHECK(stepper->name() == "implicit_euler");
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  for (int k = 0; k < 5; ++k) REQUIRE(stepper->step(0.01, x, v));
  CHECK(stepper->counters().newton_iterations == 5);
  CHECK(stepper->counters().factorizations == 5);
  // modified Newton keeps its factorization across steps (Chapter 9's StageNewton): fewer factorizations
  MethodSettings modified;
  modified.newton.variant = NewtonVariant::modified;
  const auto kept = make_stepper("implicit_euler", field, modified);
  Vector xm = scene.initial_positions(), vm = scene.initial_velocities();
  for (int k = 0; k < 5; ++k) REQUIRE(kept->step(0.01, xm, vm));
  CHECK(kept->counters().factorizations < kept->counters().newton_iterations);
}

TEST_CASE("each settings table names every value once and parses its names back; unknown names list the others") {
  const auto check_table = [](const auto& table, int values) {
    INFO(table.what());
    CHECK(static_cast<int>(table.entries().size()) == values);
    std::set<std::string> names;
    for (const auto& e : table.entries()) {
      CHECK(names.insert(e.name).second);
      CHECK(table.parse(e.name) == e.value);
      CHECK(std::string(table.name(e.value)) == e.name);
    }
    const std::string why = refusal([&] { (void)table.parse("nonsense"); });
    CHECK(contains(why, "unknown " + table.what() + " 'nonsense': expected one of " + table.accepted()));
  };
  check_table(linear_solvers(), 5);
  check_table(stiffness_treatments(), 3);
  check_table(newton_variants(), 3);
  check_table(method_families(), 5);
  CHECK(linear_solvers().accepted("|") == "ldlt|ldu|cg|lu|automatic");
}
