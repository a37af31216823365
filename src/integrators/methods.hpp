// Every integrator of the book by name, so that comparison chapters (5, 6, 7) can loop over methods.
#pragma once

#include "integrators/implicit_euler.hpp"
#include "integrators/stepper.hpp"

#include <memory>
#include <string>
#include <vector>

namespace cloth {

/// Names accepted by make_stepper: explicit_euler, symplectic_euler, every built-in tableau (euler, heun,
/// midpoint, kutta3, rk4, rule38), implicit_euler (full Newton) and implicit_euler_1newton (one iteration).
std::vector<std::string> method_names();

/// The stepper called `method` on `field`; `newton` sets the implicit methods' solver and tolerance (its
/// max_iterations is replaced by 1 for implicit_euler_1newton). Throws InputError for an unknown name.
std::unique_ptr<Stepper> make_stepper(const std::string& method, ForceField& field, NewtonSettings newton = {});

}  // namespace cloth
