// Chapter 10's single run: any method of the registry, by name, on any scene of the common flags, with the
// settings of the method it names (Newton's for the implicit methods, iterations and substeps for local/global,
// XPBD and small steps); it writes the standard outputs and the largest spring strain it recorded.
#include "analysis/spring_strain.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/newton_stepper.hpp"
#include "integrators/simulate.hpp"
#include "program/command_line.hpp"
#include "program/limits.hpp"
#include "program/method_flags.hpp"
#include "program/output.hpp"
#include "program/progress.hpp"
#include "program/run_outputs.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// run.txt's lines of the method's settings, and the stretch it let through at the recorded states.
KeyValues run_lines(const Stepper& stepper, const RunResult& result) {
  KeyValues lines;
  if (const auto* implicit = dynamic_cast<const NewtonStepper*>(&stepper)) {
    lines = newton_run_lines(implicit->settings());
    // Where Newton's work goes on a frame step (the robust implicit step's section): halved updates, and
    // factorizations of an exact Newton matrix that was indefinite.
    lines.emplace_back("line_search_halvings", std::to_string(result.counters.line_search_halvings));
    lines.emplace_back("indefinite_factorizations", std::to_string(result.counters.indefinite_factorizations));
  }
  for (const auto& line : IterationFlags::run_lines(stepper)) lines.push_back(line);
  double strain = -1;
  for (const Frame& f : result.frames)
    strain = std::max(strain, largest_spring_strain(stepper.field().scene(), f.positions));
  lines.emplace_back("largest_strain_frames", format_number(strain, 6));
  return lines;
}

}  // namespace

int main(int argc, char** argv) {
  std::string method_name = "implicit_euler";
  NewtonFlags newton;
  IterationFlags iterations;
  CommandLine cli("ch10_cloth",
                  "Chapter 10: one run of the cloth with any method of the registry, at fixed steps (an embedded pair\n"
                  "advances with its b row, without step control: that is ch08_adaptive_step's).");
  std::string names;
  for (const std::string& name : method_names()) names += (names.empty() ? "" : ", ") + name;
  cli.add_value("--method", "NAME", "a method of the registry (" + names + "; default implicit_euler)",
                [&](const std::string& s) { method_name = s; });
  newton.add_to(cli);
  iterations.add_to(cli);
  cli.declare_outputs([](const Options&) { return run_output_specs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const Method* method = nullptr;
    try {
      method = &find_method(method_name);
    } catch (const InputError& e) {
      throw InputError(std::string("--method: ") + e.what());
    }
    // The methods that factor a sparse matrix need its memory, beyond what parse checked for an explicit run.
    if (method->family == MethodFamily::implicit_runge_kutta || method->family == MethodFamily::multistep)
      require_run_memory(opt.scene, opt.run, implicit_bytes_per_particle(opt.scene.grid.particle_count()));
    const Scene scene(opt.scene);
    ForceField field(scene);
    const MethodSettings settings = method_settings(*method, scene, newton, iterations);
    std::unique_ptr<Stepper> stepper;
    try {
      stepper = method->stepper(field, settings);
    } catch (const InputError& e) {
      throw InputError("--method " + method->name + ": " + e.what());
    }
    prepare_declared_outputs(opt.run.out_dir, run_output_specs());

    RunSettings run = opt.run;
    run.progress = terminal_progress(cli.program());
    const RunResult result = simulate(*stepper, run);
    return finish_run(result, *stepper, run, cli.program(), run_lines(*stepper, result));
  });
}
