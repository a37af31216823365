// The method registry: names to steppers.
#include "integrators/methods.hpp"

#include "base/input_error.hpp"
#include "integrators/explicit_euler.hpp"
#include "integrators/explicit_runge_kutta.hpp"
#include "integrators/symplectic_euler.hpp"

namespace cloth {

std::vector<std::string> method_names() {
  std::vector<std::string> names = {"explicit_euler", "symplectic_euler"};
  for (const ButcherTableau& t : builtin_tableaus()) names.push_back(t.name);
  names.emplace_back("implicit_euler");
  names.emplace_back("implicit_euler_1newton");
  return names;
}

std::unique_ptr<Stepper> make_stepper(const std::string& method, ForceField& field, NewtonSettings newton) {
  if (method == "explicit_euler") return std::make_unique<ExplicitEuler>(field);
  if (method == "symplectic_euler") return std::make_unique<SymplecticEuler>(field);
  if (method == "implicit_euler") return std::make_unique<ImplicitEuler>(field, newton);
  if (method == "implicit_euler_1newton") {
    newton.max_iterations = 1;
    return std::make_unique<ImplicitEuler>(field, newton);
  }
  for (const ButcherTableau& t : builtin_tableaus())
    if (t.name == method) return std::make_unique<ExplicitRungeKutta>(field, t);
  std::string names;
  for (const std::string& n : method_names()) names += (names.empty() ? "" : ", ") + n;
  throw InputError("unknown method '" + method + "': expected one of " + names);
}

}  // namespace cloth
