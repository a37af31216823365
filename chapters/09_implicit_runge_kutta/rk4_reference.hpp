// The reference of both Chapter 9 programs' accuracy studies: RK4 at a small step, explicit and sharing no code with
// the implicit methods or with SUNDIALS.
#pragma once

#include "model/force_field.hpp"

namespace ch09 {

/// The free particles' positions at T by RK4 at the step h_ref from the scene's initial state. Throws
/// std::runtime_error if the run fails, Interrupted if a signal stopped it.
cloth::Vector rk4_positions(cloth::ForceField& field, double T, double h_ref);

}  // namespace ch09
