// Chapter 9's reference point: the same cloth integrated by SUNDIALS (Hindmarsh et al. 2005; Gardner et al. 2022),
// CVODE's variable-order BDF and ARKODE's diagonally implicit methods, each Newton system solved by KLU (Davis &
// Palamadai Natarajan 2010) on the analytic sparse Jacobian of the model. One SUNDIALS run by default; with
// --report-runs, the chapter's comparisons with the book's own methods, each in a file named for what it compares.
#include "benchmark.hpp"

#include "base/input_error.hpp"
#include "program/fragment.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"
#include "program/output_kinds.hpp"
#include "program/output_spec.hpp"
#include "program/run_outputs.hpp"

#include <string>

using namespace cloth;

namespace {

// What the command line chose beyond the common flags.
struct Flags {
  ch09::SundialsSettings settings{"cvode-bdf"};
  bool compare = false, report_runs = false, quick = false;
};

constexpr const char* solvers[] = {"cvode-bdf", "arkode-esdirk32", "arkode-esdirk43", "arkode-dirk",
                                   "arkode-backward-euler"};

void add_flags(CommandLine& cli, Flags& flags) {
  cli.add_value("--solver", "cvode-bdf|arkode-esdirk32|arkode-esdirk43|arkode-dirk|arkode-backward-euler",
                "CVODE's BDF, ARKODE's ESDIRK3(2)4L[2]SA, ESDIRK4(3)6L[2]SA or default ARK3(2)4L[2]SA ESDIRK (all with "
                "step control), or backward Euler at the fixed step --dt (default cvode-bdf)",
                [&](const std::string& s) {
                  for (const char* name : solvers)
                    if (s == name) {
                      flags.settings.solver = s;
                      return;
                    }
                  throw InputError("unknown solver '" + s + "': expected cvode-bdf, arkode-esdirk32, arkode-esdirk43, "
                                   "arkode-dirk or arkode-backward-euler");
                });
  cli.add_value("--jacobian", "exact|symmetric|definite",
                "df/dx in the Jacobian SUNDIALS is given: exact, or as the book's Newton matrix of that treatment "
                "holds it (default exact)",
                [&](const std::string& s) { flags.settings.treatment = stiffness_treatments().parse(s); });
  const auto tolerance = [](double& tol) {
    return [&tol](const std::string& s) {
      tol = parse_number(s);
      if (!(tol > 0) || tol >= 1) throw InputError("expected a number in (0, 1), got " + s);
    };
  };
  cli.add_value("--rtol", "TOL", "SUNDIALS' relative tolerance (default 1e-6)", tolerance(flags.settings.rtol));
  cli.add_value("--atol", "TOL", "SUNDIALS' absolute tolerance (default 1e-6)", tolerance(flags.settings.atol));
  cli.add_switch("--compare", "afterwards, the largest position error at T against RK4 at h = 1e-5 (not timed)",
                 [&] { flags.compare = true; });
  cli.add_switch("--report-runs",
                 "the chapter's comparisons: CVODE against the book's SDIRKs on (K, D) = (5000, 20) over T = 0.4 s, "
                 "and ARKODE's backward Euler against the book's on (200, 20) over T = 1 s (processor time, best of 3)",
                 [&] { flags.report_runs = true; });
  cli.add_switch("--quick", "with --report-runs: one timing per run (the plots target)", [&] { flags.quick = true; });
  // No --frames: the program writes final.dat and run.txt, no frames.
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--K-flexion", "--damping", "--damping-model", "--springs",
                  "--pins", "--v0", "--dt", "--t-end", "--out"});
}

// KLU's factors of the 6n first-order system, far more than an explicit run's vectors (parse's check).
void require_klu_memory(const Options& opt) {
  const long long particles = static_cast<long long>(opt.scene.grid.M) * opt.scene.grid.N;
  const std::string grid = std::to_string(opt.scene.grid.M) + "x" + std::to_string(opt.scene.grid.N);
  require_memory(static_cast<double>(particles) * sundials_klu_bytes_per_particle(particles), "--grid",
                 "a SUNDIALS run with KLU on a " + grid + " grid", ": expected a smaller grid");
}

// What each mode writes into --out, declared once (program/output_spec.hpp).
OutputList single_run_outputs() {
  return {{"final.dat", OutputKind::data, "every particle's position and velocity at the end of the run"},
          {"run.txt", OutputKind::data, "the solver, its tolerances, its work counters and how the run ended"}};
}

OutputList report_outputs() {
  using namespace cloth::output_kinds;
  return {{"stiff_runs.dat", figure, "every run on the stiff cloth: error, time and work"},
          {"stiff_comparison.md", fragment, "for each error level, each side's fastest run reaching it"},
          {"stiff_work.md", fragment, "the work of those runs: factorizations, Jacobians, Newton iterations, forces"},
          {"stiff_reference.md", fragment, "how far the reference moves when its step is halved"},
          {"report_scene.md", fragment, "implicit Euler on the report scene, ARKODE's against the book's"}};
}

}  // namespace

int main(int argc, char** argv) {
  Flags flags;
  CommandLine cli("ch09_sundials_benchmark",
                  "Chapter 9: the cloth integrated by SUNDIALS (CVODE BDF, ARKODE's ESDIRKs, ARKODE backward Euler)\n"
                  "with KLU on the analytic Jacobian, for comparison with ch09_implicit_runge_kutta.");
  add_flags(cli, flags);
  cli.declare_outputs([&](const Options&) { return flags.report_runs ? report_outputs() : single_run_outputs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    if (flags.report_runs) {
      refuse_unused(opt, "--report-runs",
                    {"--solver", "--jacobian", "--rtol", "--atol", "--compare", "--K", "--damping", "--dt", "--t-end"},
                    "its runs set their own solvers, tolerances, stiffness, damping, steps and horizons");
      require_klu_memory(opt);
      prepare_declared_outputs(opt.run.out_dir, report_outputs(), single_run_outputs());
      const std::string command = reader_command(argc, argv);
      ch09::stiff_comparison(opt.scene, flags.quick, opt.run.out_dir, command);         // stiff_comparison.md
      ch09::report_scene_comparison(opt.scene, flags.quick, opt.run.out_dir, command);  // report_scene.md
      return 0;
    }
    if (flags.quick) throw InputError("--quick: only with --report-runs");
    const std::string& solver = flags.settings.solver;
    if (solver != "arkode-backward-euler" && opt.has("--dt"))
      throw InputError("--dt: " + solver + " chooses its own steps; --dt is the fixed step of --solver "
                       "arkode-backward-euler");
    require_klu_memory(opt);
    prepare_declared_outputs(opt.run.out_dir, single_run_outputs(), report_outputs());
    ch09::SundialsSettings settings = flags.settings;
    settings.T = opt.run.t_end;
    settings.h = opt.run.dt;
    return ch09::single_run(opt, settings, flags.compare, cli.program());
  });
}
