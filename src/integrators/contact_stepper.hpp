// Contact for any one-step method (Chapter 11): a Stepper that wraps another, lets it take the step as if there
// were no obstacles, then corrects the end state for contact and friction (contact/obstacles.hpp).
#pragma once

#include "contact/obstacles.hpp"
#include "contact/self_collision.hpp"
#include "integrators/stepper.hpp"

#include <memory>
#include <optional>

namespace cloth {

/// Why a wrapper rather than a hook in the driver: a Stepper is what every family of the registry is (explicit
/// and embedded Runge-Kutta, symplectic Euler, the Newton-based implicit methods) and what both drivers and every
/// test take, so wrapping one gives each of them contact with no change to the drivers; and the correction stays
/// part of the step, so a step that is accepted is one whose end state is already out of the obstacles. XPBD is
/// the exception that takes contact inside its step: wrapped, it is handed the model and projects the contacts as
/// inequality constraints in every substep (Xpbd::set_contact). Implicit Euler wrapped is corrected after its
/// step like the explicit methods; ContactImplicitEuler enforces contact inside its linear solve instead.
class ContactStepper final : public Stepper {
 public:
  /// Wraps `inner` (which must step on `inner->field()`); the model must pass validate(ContactModel).
  ContactStepper(std::unique_ptr<Stepper> inner, ContactModel model);

  /// The wrapped method's name: contact changes the scene, not the method.
  [[nodiscard]] std::string name() const override { return inner_->name(); }

  /// The inner step, then resolve_obstacle_contacts on its end state. With self-collision, the displacement is
  /// clamped first, and self-contacts and obstacle contacts are resolved in turn until no pair is left (at most
  /// max_self_passes passes). Counts the inner stepper's work as its own.
  bool step(double h, Vector& x, Vector& v) override;

  [[nodiscard]] const ContactModel& model() const { return model_; }
  [[nodiscard]] const Stepper& inner() const { return *inner_; }
  /// Particle-obstacle contacts corrected by the last step.
  [[nodiscard]] int last_contacts() const { return last_contacts_; }
  /// The self-collision state (its work and time), when the model asks for it.
  [[nodiscard]] const SelfCollision* self_collision() const { return self_ ? &*self_ : nullptr; }
  static constexpr int max_self_passes = 16;
  /// Hash builds in one step at most: the step's first, and rebuilds after passes that moved a particle beyond the
  /// candidates' margin.
  static constexpr int max_self_rounds = 3;

 private:
  void correct_with_self_collision(double h, Vector& x, Vector& v);

  std::unique_ptr<Stepper> inner_;
  ContactModel model_;
  Vector x0_;  // the step's start positions, which the friction rule measures the displacement from
  std::optional<SelfCollision> self_;
  int last_contacts_ = 0;
};

}  // namespace cloth
