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

std::string ImplicitEuler::name() const { return "implicit_euler"; }

}  // namespace cloth
