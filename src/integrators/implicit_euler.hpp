// Implicit (backward) Euler with Newton's method, Chapter 4: solve M (v1 - v0) = h f(x0 + h v1, v1) for v1 on
// the analytic sparse Jacobian J = M - h df/dv - h^2 df/dx, then x1 = x0 + h v1. It is the one-stage case of
// Chapter 9's diagonally implicit Runge-Kutta engine (the tableau c = A = b = 1), and its Newton iteration is
// that engine's StageNewton.
#pragma once

#include "integrators/diagonally_implicit_runge_kutta.hpp"

namespace cloth {

/// The implicit_euler tableau on the stage machinery; the Newton variant and the solver are settings, written
/// beside it in run.txt.
class ImplicitEuler final : public DiagonallyImplicitRungeKutta {
 public:
  ImplicitEuler(ForceField& field, NewtonSettings settings);
};

}  // namespace cloth
