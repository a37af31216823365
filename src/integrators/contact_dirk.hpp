// A diagonally implicit Runge-Kutta method with contact inside each stage's solve (Chapter 11): every stage is an
// implicit Euler equation of step h a_ii from its own start, so Baraff and Witkin's filtered step solves it with
// the particles in contact constrained, and the stage's effective force, the obstacles' impulse included, feeds the
// stages after it.
#pragma once

#include "contact/obstacles.hpp"
#include "integrators/contact_implicit_euler.hpp"
#include "integrators/implicit_tableaus.hpp"
#include "integrators/stepper.hpp"

#include <memory>
#include <string>
#include <vector>

namespace cloth {

/// For a stiffly accurate tableau whose every stage is implicit (a_ii > 0: sdirk2, sdirk3), stage i starts at
///   x~_i = x0 + h sum_{j<i} a_ij V_j,  v~_i = v0 + (h/m) sum_{j<i} a_ij F_j,
/// and its equation M (V_i - v~_i) = h a_ii f(x~_i + h a_ii V_i, V_i) is implicit Euler's with step h a_ii from
/// (x~_i, v~_i), which ContactImplicitEuler solves with the contacts filtered inside CG (one iteration, or Newton's
/// iteration, FilteredNewton), then corrects for contacts that began during it. Its effective force
/// F_i = m (V_i - v~_i) / (h a_ii) holds the obstacles' impulse and the friction, so a later stage starts from a
/// velocity that has already met the obstacle. The last stage's end is the step: x1 = x~_s + h a_ss V_s, v1 = V_s
/// (stiffly accurate), so the displacement and the velocity come from one filtered solve and agree.
class ContactDirk final : public Stepper {
 public:
  /// Throws InputError when the tableau is not stiffly accurate or has an explicit stage.
  ContactDirk(ForceField& field, ImplicitTableau tableau, const ContactModel& model, FilteredNewton newton = {});

  [[nodiscard]] std::string name() const override { return tableau_.method.name; }
  bool step(double h, Vector& x, Vector& v) override;

 private:
  bool stage_failed(int i);  // the stage's failure as the step's, named; returns false
  void count_stages_work();
  ImplicitTableau tableau_;
  std::vector<std::unique_ptr<ContactImplicitEuler>> stages_;  // one per stage: each keeps its own released set
  std::vector<Vector> V_, F_;
  Vector x_tilde_, v_tilde_, x_stage_;
};

}  // namespace cloth
