// Implicit Euler: the one-stage diagonally implicit method.
#include "integrators/implicit_euler.hpp"

namespace cloth {

ImplicitEuler::ImplicitEuler(ForceField& field, NewtonSettings settings)
    : DiagonallyImplicitRungeKutta(field, builtin_implicit_tableau("implicit_euler"), settings) {}

}  // namespace cloth
