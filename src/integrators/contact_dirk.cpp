// SDIRK with Baraff and Witkin's filtered solve in every stage.
#include "integrators/contact_dirk.hpp"

#include "base/input_error.hpp"

#include <utility>

namespace cloth {

ContactDirk::ContactDirk(ForceField& field, ImplicitTableau tableau, const ContactModel& model,
                         FilteredNewton newton)
    : Stepper(field), tableau_(std::move(tableau)), x_tilde_(field.dof_count()), v_tilde_(field.dof_count()),
      x_stage_(field.dof_count()) {
  const ButcherTableau& t = tableau_.method;
  bool implicit = true;
  for (int i = 0; i < t.stages(); ++i) implicit = implicit && t.A(i, i) > 0;
  if (!tableau_.stiffly_accurate() || !implicit) {
    std::string message(t.name);
    message += ": contact inside the stages needs a stiffly accurate tableau whose every stage is implicit";
    throw InputError(message);
  }
  for (int i = 0; i < t.stages(); ++i) {
    stages_.push_back(std::make_unique<ContactImplicitEuler>(field, model, newton));
    V_.emplace_back(field.dof_count());
    F_.emplace_back(field.dof_count());
  }
}

// [contact_dirk_step]
bool ContactDirk::step(double h, Vector& x, Vector& v) {
  const ButcherTableau& t = tableau_.method;
  const double m = field_.scene().params().mass;
  for (int i = 0; i < t.stages(); ++i) {
    const auto si = static_cast<std::size_t>(i);
    x_tilde_ = x;
    v_tilde_ = v;
    for (int j = 0; j < i; ++j) {
      const double a = t.A(i, j);
      x_tilde_ += (h * a) * V_[static_cast<std::size_t>(j)];
      v_tilde_ += (h * a / m) * F_[static_cast<std::size_t>(j)];
    }
    const double gamma = h * t.A(i, i);
    x_stage_ = x_tilde_;
    V_[si] = v_tilde_;
    if (!stages_[si]->step(gamma, x_stage_, V_[si])) return stage_failed(i);  // x_stage_ = x~ + gamma V_i
    F_[si] = (m / gamma) * (V_[si] - v_tilde_);  // f and the obstacles' impulse over the stage
  }
  x = x_stage_;
  v = V_.back();
  count_stages_work();
  return true;
}
// [contact_dirk_step]

bool ContactDirk::stage_failed(int i) {
  failure_ = stages_[static_cast<std::size_t>(i)]->failure();
  std::string reason("stage ");
  reason += std::to_string(i + 1);
  reason += ": ";
  reason += failure_.reason;
  failure_.reason = reason;
  return false;
}

// The stages' work is the step's.
void ContactDirk::count_stages_work() {
  const long long steps = counters_.steps + 1;
  counters_ = {};
  for (const auto& stage : stages_) {
    const StepCounters& c = stage->counters();
    counters_.rhs_evaluations += c.rhs_evaluations;
    counters_.jacobian_assemblies += c.jacobian_assemblies;
    counters_.linear_solves += c.linear_solves;
    counters_.cg_iterations += c.cg_iterations;
    counters_.newton_iterations += c.newton_iterations;
  }
  counters_.steps = steps;
}

}  // namespace cloth
