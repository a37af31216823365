// The rule of the page's "what each method needs" section, as code.
#include "steppers.hpp"

#include "base/input_error.hpp"
#include "integrators/contact_implicit_euler.hpp"
#include "integrators/contact_stepper.hpp"

#include <algorithm>
#include <string>

using namespace cloth;

namespace ch11 {

namespace {

// Implicit Euler with contact filtered inside CG: CG needs the definite matrix, and the filter is Newton's own
// solve, so `--newton one|full`, `--newton-tol` and `--newton-max-iter` apply and the other flags are refused.
std::unique_ptr<Stepper> filtered_implicit_euler(ForceField& field, const ContactModel& model,
                                                 const NewtonFlags& newton, KeyValues& lines) {
  if (model.self_collision)
    throw InputError("--method implicit_euler: the filtered step does not take self-collision, which the fold "
                     "scene needs: expected another method (implicit_euler runs the incline and the sphere)");
  const NewtonSettings& s = newton.given();
  if (s.variant == NewtonVariant::modified)
    throw InputError("--newton modified: implicit_euler with contact refactors nothing (its CG needs no "
                     "factorization): expected one or full");
  if (s.solver != LinearSolverKind::automatic && s.solver != LinearSolverKind::cg)
    throw InputError("--linear-solver: implicit_euler with contact solves by filtered conjugate gradients: "
                     "expected cg");
  if (newton.jacobian() && *newton.jacobian() != StiffnessTreatment::definite)
    throw InputError("--jacobian: filtered conjugate gradients need the definite matrix: expected definite");
  // Without --newton, Baraff and Witkin's single iteration, unless a tolerance or an iteration cap asks for more
  // (the other flags choose nothing that one iteration does not have).
  const bool asks_for_more = newton.given("--newton-tol") || newton.given("--newton-max-iter");
  const NewtonVariant variant = newton.given("--newton") ? s.variant
                                : asks_for_more          ? NewtonVariant::full
                                                         : filtered_newton_default.variant;
  if (variant == NewtonVariant::one && newton.given("--newton-max-iter") && s.max_iterations != 1)
    throw InputError("--newton-max-iter: --newton one takes exactly one iteration; leave --newton-max-iter out");
  const bool iterate = variant == NewtonVariant::full && s.max_iterations != 1;
  FilteredNewton settings;
  if (iterate) settings = {s.max_iterations, s.tolerance};
  lines.emplace_back("contact", "filtered_cg");
  lines.emplace_back("newton", iterate ? "full" : "one");
  return std::make_unique<ContactImplicitEuler>(field, model, settings);
}

}  // namespace

std::unique_ptr<Stepper> contact_stepper(const Method& method, ForceField& field, const ContactModel& model,
                                         const NewtonFlags& newton, const IterationFlags& iterations,
                                         KeyValues& lines) {
  if (method.name == "implicit_euler") return filtered_implicit_euler(field, model, newton, lines);
  MethodSettings settings;
  const std::vector<const Method*> implicit = newton_methods();
  if (std::find(implicit.begin(), implicit.end(), &method) != implicit.end())
    settings.newton = newton.settings_for(field.scene());
  else if (!newton.first_given().empty())
    throw InputError(newton.first_given() + ": " + method.name + " has no Newton iteration to set");
  iterations.apply(method, settings);
  lines.emplace_back("contact", method.family == MethodFamily::position_based ? "inequality_constraints" : "after_step");
  try {
    return std::make_unique<ContactStepper>(method.stepper(field, settings), model);
  } catch (const InputError& e) {
    throw InputError("--method " + method.name + ": " + e.what());
  }
}

}  // namespace ch11
