// Chapter 8: adaptive step size from an embedded Runge-Kutta pair. One run of the report's cloth with error
// control (the common flags, --tableau, --tol or --rtol/--atol, --first-step, --controller), or with
// --experiments the chapter's studies (experiments.cpp); --quick makes those short enough for the plots target.
#include "experiments.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "base/text.hpp"
#include "integrators/adaptive_simulate.hpp"
#include "integrators/method_registry.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"
#include "program/output_spec.hpp"
#include "program/run_outputs.hpp"

#include <cmath>
#include <optional>
#include <string>

using namespace cloth;

namespace {

// A tolerance flag's value: a positive finite number.
double positive(const std::string& text) {
  const double value = parse_number(text);
  if (!(value > 0)) throw InputError("'" + text + "' is not a positive number");
  return value;
}

// The files one run writes into --out, declared once (program/output_spec.hpp); with --experiments, the studies'
// (experiments.hpp).
OutputList single_run_outputs() {
  return run_output_specs() +
         OutputList{{"steps.dat", OutputKind::data, "every attempted step: t, h, error, accepted"}};
}

// steps.dat: every attempted step.
void write_steps(const std::string& path, const std::vector<StepAttempt>& attempts) {
  OutputFile out(path);
  std::fprintf(out.get(), "# t h error_in_tolerances accepted(1)/rejected(0)\n");
  for (const StepAttempt& a : attempts)
    std::fprintf(out.get(), "%.17g %.10g %.6e %d\n", a.t, a.h, a.error, a.accepted ? 1 : 0);
  out.commit();
}

int run_once(const Options& opt, const ButcherTableau& tableau, const std::string& source,
             const AdaptiveSettings& settings, const std::string& program) {
  const Scene scene(opt.scene);
  ForceField field(scene);
  EmbeddedRungeKutta rk(field, tableau);
  const AdaptiveResult result = adaptive_simulate(rk, opt.run, settings);
  const auto num = [](double x) { return format_number(x, 10); };
  std::vector<std::pair<std::string, std::string>> extra = {{"tableau", tableau.name},
                 {"tableau_source", source},
                 {"stages", std::to_string(tableau.stages())},
                 {"order", std::to_string(tableau.order)},
                 {"embedded_order", std::to_string(tableau.embedded_order)},
                 {"first_same_as_last", tableau.first_same_as_last() ? "yes" : "no"},
                 {"rtol", num(settings.tolerances.rtol)},
                 {"atol", num(settings.tolerances.atol)},
                 {"norm", norm_name(settings.tolerances.norm)},
                 {"controller", controller_name(settings.controller)},
                 {"max_spring_turn", settings.max_spring_turn > 0 ? num(settings.max_spring_turn) : "none"},
                 {"first_step", settings.first_step > 0 ? num(settings.first_step) : "automatic"},
                 {"accepted_steps", std::to_string(result.accepted)},
                 {"rejected_steps", std::to_string(result.rejected)},
                 {"smallest_step", num(result.smallest_step)},
                 {"largest_step", num(result.largest_step)},
                 {"refused_for_turn", std::to_string(result.refused_for_turn)}};
  write_steps(opt.run.out_dir + "/steps.dat", result.attempts);
  // Not finish_run: its note on frames counts fixed steps of --dt, and adaptive frames are interpolated, all of them.
  write_outputs(result, rk, opt.run, extra);
  return report(result, rk, program);
}

}  // namespace

int main(int argc, char** argv) {
  std::string tableau_argument = "dopri5";
  std::optional<double> tol, rtol, atol;
  AdaptiveSettings settings;
  bool experiments = false, quick = false;
  CommandLine cli("ch08_adaptive_step",
                  "Chapter 8: adaptive step size from an embedded Runge-Kutta pair on the report's cloth.");
  // Every common flag but --dt: the step is chosen by error control.
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--K-flexion", "--damping", "--damping-model", "--springs",
                  "--pins", "--v0", "--swing", "--t-end", "--frames", "--out"});
  std::string pair_names;
  for (const Method* m : methods_of(MethodFamily::embedded_runge_kutta))
    pair_names += (pair_names.empty() ? "" : ", ") + m->name;
  cli.add_value("--tableau", "NAME|FILE",
                "an embedded pair of the method registry: " + pair_names +
                    " (default dopri5), or a tableau file with a 'bhat' row",
                [&](const std::string& s) { tableau_argument = s; });
  cli.add_value("--tol", "TOL", "rtol = atol = TOL (default 1e-6)", [&](const std::string& s) { tol = positive(s); });
  cli.add_value("--rtol", "R", "relative tolerance (default 1e-6)", [&](const std::string& s) { rtol = positive(s); });
  cli.add_value("--atol", "A", "absolute tolerance [m, m/s] (default 1e-6)",
                [&](const std::string& s) { atol = positive(s); });
  cli.add_value("--first-step", "H", "the first step [s] (default: chosen automatically)",
                [&](const std::string& s) { settings.first_step = positive(s); });
  cli.add_value("--controller", "elementary|pi", "step-size controller (default pi)",
                [&](const std::string& s) { settings.controller = controller_from_name(s); });
  cli.add_value("--max-spring-turn", "RAD",
                "also refuse steps across which a spring turns by more than RAD (default: no such check)",
                [&](const std::string& s) { settings.max_spring_turn = positive(s); });
  std::optional<NormKind> norm;
  cli.add_value("--norm", "rms|max", "error norm over the state's components (default rms)",
                [&](const std::string& s) { norm = norm_from_name(s); });
  cli.add_switch("--experiments", "the chapter's studies instead of one run: their data, and the tables of the book's page, in --out",
                 [&] { experiments = true; });
  cli.add_switch("--quick", "with --experiments: the reduced studies of the plots target", [&] { quick = true; });
  cli.declare_outputs([&](const Options&) { return experiments ? ch08::experiment_outputs() : single_run_outputs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    if (experiments)
      refuse_unused(opt, "--experiments",
                    {"--tableau", "--tol", "--rtol", "--atol", "--first-step", "--controller", "--max-spring-turn",
                     "--norm", "--t-end", "--frames"},
                    "its studies choose their own pairs, tolerances, controllers and horizon, and record no frames");
    if (tol && (rtol || atol)) throw InputError("--tol: sets rtol and atol both; give either --tol or --rtol/--atol");
    settings.tolerances = {tol.value_or(rtol.value_or(1e-6)), tol.value_or(atol.value_or(1e-6)),
                           norm.value_or(NormKind::rms)};
    if (quick && !experiments) throw InputError("--quick: only with --experiments");
    if (experiments) {
      prepare_declared_outputs(opt.run.out_dir, ch08::experiment_outputs(), single_run_outputs());
      ch08::run_experiments(opt, quick, reader_command(argc, argv));
      return 0;
    }
    ButcherTableau tableau;
    try {
      tableau = embedded_tableau_from_argument(tableau_argument);
    } catch (const InputError& e) {
      throw InputError(std::string("--tableau: ") + e.what());
    }
    const std::string source = tableau.name == tableau_argument ? "builtin" : escaped(tableau_argument);
    prepare_declared_outputs(opt.run.out_dir, single_run_outputs(), ch08::experiment_outputs());
    return run_once(opt, tableau, source, settings, cli.program());
  });
}
