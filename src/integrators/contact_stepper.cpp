// The contact wrapper: the inner method's step, then the obstacle correction of its end state.
#include "integrators/contact_stepper.hpp"

#include "integrators/xpbd.hpp"

#include <ctime>
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
  if (model_.self_collision) self_.emplace(field_.scene().initial_positions(), model_.thickness, model_.skin);
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
  if (self_) correct_with_self_collision(h, x, v);
  else last_contacts_ = resolve_obstacle_contacts(model_, x0_, x, v);
  return true;
}
// [contact_step]

// [self_step]
void ContactStepper::correct_with_self_collision(double h, Vector& x, Vector& v) {
  // Processor time, not the wall clock: other processes on the machine do not count (the stepping loop runs on one
  // thread, so the process's clock is the thread's).
  const std::clock_t start = std::clock();
  // The clamp, the obstacles and the margin's measure, in one sweep over the particles.
  last_contacts_ = self_->clamp_and_correct(model_, x0_, h, x, v);
  const std::clock_t swept = std::clock();
  self_->add_sweep_seconds(static_cast<double>(swept - start) / CLOCKS_PER_SEC);
  // The candidates of the last build while no particle moved a quarter thickness since; parting a pair may push a
  // particle into the ground or towards a third one: alternate until nothing moves. The passes move particles
  // too, so the list is checked again after them: when they carried a particle beyond the margin, the hash is
  // rebuilt and the passes run on the new list.
  self_->update_candidates(x);
  for (int round = 1;; ++round) {
    const std::clock_t passes_start = std::clock();
    for (int pass = 0; pass < max_self_passes; ++pass) {
      if ((pass == 0 ? self_->resolve(x, v) : self_->resolve_again(x, v)) == 0) break;
      self_->correct_moved(model_, x0_, x, v);  // the others are as the last correction left them
    }
    self_->add_pass_seconds(static_cast<double>(std::clock() - passes_start) / CLOCKS_PER_SEC);
    if (round == max_self_rounds || !self_->moved_beyond_margin(x)) break;
    self_->find_candidates(x);
  }
  self_->add_seconds(static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
}
// [self_step]

}  // namespace cloth
