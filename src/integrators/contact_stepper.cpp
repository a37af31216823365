// The contact wrapper: the inner method's step, then the obstacle correction of its end state.
#include "integrators/contact_stepper.hpp"

#include "integrators/xpbd.hpp"

#include <utility>

namespace cloth {

namespace {

// total += after - before, field by field: the work the inner stepper did in one step.
void add_work(StepCounters& total, const StepCounters& before, const StepCounters& after) {
  total.steps += after.steps - before.steps;
  total.rhs_evaluations += after.rhs_evaluations - before.rhs_evaluations;
  total.jacobian_assemblies += after.jacobian_assemblies - before.jacobian_assemblies;
  total.factorizations += after.factorizations - before.factorizations;
  total.linear_solves += after.linear_solves - before.linear_solves;
  total.cg_iterations += after.cg_iterations - before.cg_iterations;
  total.newton_iterations += after.newton_iterations - before.newton_iterations;
  total.line_search_halvings += after.line_search_halvings - before.line_search_halvings;
}

}  // namespace

ContactStepper::ContactStepper(std::unique_ptr<Stepper> inner, ContactModel model)
    : Stepper(inner->field()), inner_(std::move(inner)), model_(std::move(model)), x0_(field_.dof_count()) {
  validate(model_);
  // XPBD takes contact inside its substeps, as inequality constraints; the correction after its step then finds
  // nothing left to do but guard the end state.
  if (auto* xpbd = dynamic_cast<Xpbd*>(inner_.get())) xpbd->set_contact(&model_);
}

// [contact_step]
bool ContactStepper::step(double h, Vector& x, Vector& v) {
  x0_ = x;
  const StepCounters before = inner_->counters();
  const bool taken = inner_->step(h, x, v);  // the step as if nothing were in the way
  add_work(counters_, before, inner_->counters());
  if (!taken) {
    failure_ = inner_->failure();
    return false;  // the inner stepper left (x, v) unchanged
  }
  last_contacts_ = resolve_obstacle_contacts(model_, x0_, x, v);
  return true;
}
// [contact_step]

}  // namespace cloth
