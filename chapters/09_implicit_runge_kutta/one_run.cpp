// One run of the chosen method on the cloth, at fixed steps or under step control (`--tol`): the model page's
// outputs, with run.txt's lines for the tableau, Newton, the linear algebra and the work.
#include "studies.hpp"

#include "base/format_number.hpp"
#include "integrators/implicit_step_control.hpp"
#include "program/output.hpp"
#include "program/run_outputs.hpp"

#include <cstdio>
#include <utility>

using namespace cloth;

namespace ch09 {
namespace {

// run.txt's lines for the method: the tableau, Newton, the linear algebra, the work.
std::vector<std::pair<std::string, std::string>> method_lines(const MethodChoice& choice, const Stepper& stepper,
                                                              const RunResult& result, const NewtonSettings& newton) {
  std::vector<std::pair<std::string, std::string>> lines;
  if (choice.multistep()) {
    lines.emplace_back("tableau", choice.row->name + " (multistep)");
    lines.emplace_back("order", "2");
  } else {
    lines.emplace_back("tableau", choice.tableau.method.name);
    lines.emplace_back("tableau_source", choice.tableau.source);
    lines.emplace_back("stages", std::to_string(choice.tableau.method.stages()));
    lines.emplace_back("order", std::to_string(choice.tableau.method.order));
  }
  lines.emplace_back("newton", newton_variant_name(newton.one_iteration() ? NewtonVariant::one : newton.variant));
  lines.emplace_back("linear_solver", linear_solver_name(resolve(newton, stepper.field().scene()).solver));
  lines.emplace_back("jacobian", stiffness_treatments().name(newton.treatment));
  lines.emplace_back("newton_tol", format_number(newton.tolerance, 10));
  lines.emplace_back("newton_test", newton.estimate_test ? "estimate" : "update_and_residual");
  lines.emplace_back("newton_max_iter", std::to_string(newton.max_iterations));
  lines.emplace_back("line_search", line_searches().name(newton.line_search));
  lines.emplace_back("linear_solves", std::to_string(result.counters.linear_solves));
  lines.emplace_back("line_search_halvings", std::to_string(result.counters.line_search_halvings));
  return lines;
}

}  // namespace

int run_cloth(const SceneParams& params, const RunSettings& run, const MethodChoice& choice,
              const std::string& program, RunResult* kept) {
  const Scene scene(params);
  validate(choice.newton, scene);  // before anything is written
  ForceField field(scene);
  const std::unique_ptr<NewtonStepper> stepper = make_method(choice, field);
  prepare_outputs(run.out_dir, run_output_names());
  RunResult result;
  std::vector<std::pair<std::string, std::string>> extra;
  if (choice.tol) {
    StepControl control;
    control.tolerance = *choice.tol;
    ControlledRun controlled =
        simulate_controlled(dynamic_cast<DiagonallyImplicitRungeKutta&>(*stepper), run, control);
    result = std::move(controlled.result);
    extra = method_lines(choice, *stepper, result, choice.newton);
    extra.emplace_back("tol", format_number(*choice.tol, 10));
    extra.emplace_back("rejected_steps", std::to_string(controlled.rejected_steps));
    extra.emplace_back("newton_failures", std::to_string(controlled.newton_failures));
    extra.emplace_back("smallest_step", format_number(controlled.smallest_step, 6));
    extra.emplace_back("largest_step", format_number(controlled.largest_step, 6));
  } else {
    result = simulate(*stepper, run);
    extra = method_lines(choice, *stepper, result, choice.newton);
    extra.emplace_back("rejected_steps", "0");
  }
  write_outputs(result, *stepper, run, extra);
  const int status = report(result, *stepper, program);
  if (result.steps > 0)
    std::printf("  Newton iterations per step: %.3f (%lld in %lld steps), %lld factorizations, %lld linear solves\n",
                static_cast<double>(result.counters.newton_iterations) / static_cast<double>(result.steps),
                result.counters.newton_iterations, result.steps, result.counters.factorizations,
                result.counters.linear_solves);
  if (kept) *kept = std::move(result);
  return status;
}

}  // namespace ch09
