// What each family of method needs to stay out of the obstacles (Chapter 11): the stepper for a method of the
// registry with contact, by the page's rule.
#pragma once

#include "contact/obstacles.hpp"
#include "integrators/method_registry.hpp"
#include "program/method_flags.hpp"
#include "program/run_outputs.hpp"

#include <memory>

namespace ch11 {

/// implicit_euler's Newton iteration without `--newton`: Baraff and Witkin's single iteration, unless `--newton-tol`
/// or `--newton-max-iter` asks for more (then full). Every other implicit method takes the shared default, full.
inline const cloth::NewtonFlags::MethodDefault filtered_newton_default{"implicit_euler", cloth::NewtonVariant::one};

/// implicit_euler: Baraff and Witkin's filtered step (one iteration, or iterated to Newton's tolerance with
/// `--newton full`; it does not take self-collision, and is refused for the fold); XPBD: contact as inequality
/// constraints in its substeps; every other method (explicit, embedded and implicit Runge-Kutta, symplectic Euler,
/// local/global, small steps): its own step, then the correction. `lines` receives run.txt's `contact` key. Throws InputError naming a flag the method cannot take.
[[nodiscard]] std::unique_ptr<cloth::Stepper> contact_stepper(const cloth::Method& method, cloth::ForceField& field,
                                                              const cloth::ContactModel& model,
                                                              const cloth::NewtonFlags& newton,
                                                              const cloth::IterationFlags& iterations,
                                                              cloth::KeyValues& lines);

}  // namespace ch11
