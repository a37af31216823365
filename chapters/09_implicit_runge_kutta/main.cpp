// Chapter 9: any diagonally implicit Runge-Kutta method, given by its Butcher tableau, and BDF2 on the report's
// cloth, every stage solved by the one Newton machinery of the library; step control for an embedded pair. One run
// by default; with --report-runs, the chapter's studies in the order of its page, each in a file named for what it
// studies: energy on the undamped cloth, observed orders, work against precision on the stiff cloth.
#include "studies.hpp"

#include "base/input_error.hpp"
#include "program/fragment.hpp"
#include "program/limits.hpp"
#include "program/method_flags.hpp"
#include "program/method_tables.hpp"
#include "program/output.hpp"
#include "program/run_outputs.hpp"

#include <optional>
#include <string>

using namespace cloth;

namespace {

// The chapter's studies, in the order of the page. Returns 128 + signal when a run was interrupted, else 0 (a run
// that fails is a result).
int report_runs(const ch09::Study& study) {
  // The page's table of the implicit rows of the registry: computed from their tableaus, not measured.
  write_text_fragment(study.dir + "/methods.md", implicit_method_table().markdown());
  if (const int status = ch09::energy_study(study); status != 0) return status;  // energy_summary.md
  ch09::orders_study(study);                                                       // orders.md
  ch09::stiff_work_precision(study);  // stiffness.md, work_precision.md
  return 0;
}

// What the command line chose beyond the common flags.
struct Flags {
  std::string tableau = "sdirk2";
  std::optional<double> tol;
  cloth::NewtonFlags newton;
  bool report_runs = false, quick = false;
  bool latest_force_guess = false, refresh_jacobian = false;  // the page's "before": the first guess and rule
};

void add_flags(CommandLine& cli, Flags& flags) {
  std::string names;
  for (const Method* m : newton_methods()) names += m->name + ", ";
  cli.add_value("--tableau", "NAME|FILE",
                "a registered implicit method (" + names + "default sdirk2) or a diagonally implicit tableau file",
                [&](const std::string& s) { flags.tableau = s; });
  cli.add_value("--tol", "TOL",
                "step control on the embedded error estimate, max |e| / (1 + |y|) <= TOL (embedded pairs only: "
                "trbdf2, esdirk32, esdirk43); --dt is then the first step",
                [&](const std::string& s) {
                  const double t = parse_number(s);
                  if (!(t > 0) || t >= 1) throw InputError("expected a number in (0, 1), got " + s);
                  flags.tol = t;
                });
  // --newton, --linear-solver, --newton-tol, --newton-max-iter, --jacobian. Modified Newton by default: it converges
  // to the same tolerance as full Newton at a fraction of its factorizations, several times faster (the page's
  // work-precision study).
  flags.newton.add_to(cli, NewtonVariant::modified);
  // The two ideas the page measures against what came before them, each switched off by its own flag.
  cli.add_switch("--latest-force-guess",
                 "start each stage's Newton iteration from the stage equation with the latest known force, not "
                 "from the step before's cubic dense output",
                 [&] { flags.latest_force_guess = true; });
  cli.add_switch("--refresh-jacobian",
                 "modified Newton evaluates the Jacobian again whenever it refactors the Newton matrix, instead of "
                 "keeping it and refactoring for a new step size alone",
                 [&] { flags.refresh_jacobian = true; });
  cli.add_switch("--report-runs",
                 "the chapter's studies: every method on the undamped cloth, orders on (K, D) = (200, 20) and work "
                 "against precision on (5000, 20) over T = 0.4 s (exit 0 even when a run fails)",
                 [&] { flags.report_runs = true; });
  cli.add_switch("--quick", "with --report-runs: fewer step sizes and one timing per run (the plots target)",
                 [&] { flags.quick = true; });
}

// The method and Newton's settings the flags chose, checked against the scene.
ch09::MethodChoice method_choice(Flags& flags, const Options& opt) {
  ch09::MethodChoice choice = ch09::choose(flags.tableau);
  choice.tol = flags.tol;
  if (choice.tol && (choice.multistep() || !choice.tableau.has_embedded()))
    throw InputError("--tol: step control needs an embedded pair, and " + choice.argument +
                     " has no embedded weights: use --tableau trbdf2, or leave --tol out for fixed steps");
  // A controlled run's defaults (the chapter's measurements): modified Newton, the stage equations as they are
  // (frozen dampers would cost a third- or fourth-order pair its order), and Newton stopped at a tenth of the
  // error tolerance (Hairer & Wanner's kappa rule: the iteration's error well below the error controlled).
  if (choice.tol)
    flags.newton.apply_defaults({NewtonVariant::modified, ch09::newton_kappa * *choice.tol, LineSearch::residual});

  // Newton's settings from their flags, with the one default rule for the Newton matrix (program/method_flags).
  choice.newton = flags.newton.settings_for(Scene(opt.scene));
  choice.newton.estimate_test = choice.tol.has_value();  // a controlled run stops Newton on its error estimate
  choice.newton.dense_output_predictor = !flags.latest_force_guess;
  choice.newton.keep_jacobian = !flags.refresh_jacobian;
  return choice;
}

}  // namespace

int main(int argc, char** argv) {
  Flags flags;
  CommandLine cli("ch09_implicit_runge_kutta",
                  "Chapter 9: a diagonally implicit Runge-Kutta method from its Butcher tableau, or BDF2, on the\n"
                  "report's cloth; each stage solved by Newton's method on M - h a_ii df/dv - (h a_ii)^2 df/dx.");
  add_flags(cli, flags);
  cli.declare_outputs([&](const Options&) { return flags.report_runs ? ch09::report_outputs() : run_output_specs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    if (flags.report_runs) {
      refuse_unused(opt, "--report-runs", {"--tableau", "--tol", "--damping"},
                    "its studies run every registered method, at fixed steps, and set their own damping");
      refuse_unused(opt, "--report-runs", {"--latest-force-guess", "--refresh-jacobian"},
                    "its studies measure the book's Newton as it is");
    }
    else if (flags.quick)
      throw InputError("--quick: only with --report-runs");
    const ch09::MethodChoice choice = method_choice(flags, opt);
    // Newton's matrices and factors: the implicit methods' memory, beyond what parse checked for an explicit run.
    const long long particles = static_cast<long long>(opt.scene.grid.M) * opt.scene.grid.N;
    require_run_memory(opt.scene, opt.run, implicit_bytes_per_particle(particles));
    if (!flags.report_runs) {
      prepare_declared_outputs(opt.run.out_dir, run_output_specs(), ch09::report_outputs());
      return ch09::run_cloth(opt.scene, opt.run, choice, cli.program());
    }
    prepare_declared_outputs(opt.run.out_dir, ch09::report_outputs(), run_output_specs());
    return report_runs({opt, choice.newton, flags.quick, opt.run.out_dir, cli.program(),
                       reader_command(argc, argv)});
  });
}
