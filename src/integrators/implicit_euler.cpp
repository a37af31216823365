// Implicit Euler: the one-stage diagonally implicit method.
#include "integrators/implicit_euler.hpp"

namespace cloth {

namespace {
const ImplicitTableau& backward_euler() {
  for (const ImplicitTableau& t : builtin_implicit_tableaus())
    if (t.method.name == "backward_euler") return t;
  return builtin_implicit_tableaus().front();  // never reached: the built-ins include it
}
}  // namespace

ImplicitEuler::ImplicitEuler(ForceField& field, NewtonSettings settings)
    : DiagonallyImplicitRungeKutta(field, backward_euler(), settings) {}

std::string ImplicitEuler::name() const {
  std::string n = settings().one_iteration() ? "implicit_euler_1newton" : "implicit_euler";
  if (settings().variant == NewtonVariant::modified && !settings().one_iteration()) n += "_modified";
  return n + "_" + linear_solver_name(settings().solver);
}

}  // namespace cloth
