// Chapter 3: any explicit Runge-Kutta method, given by its Butcher tableau (a built-in name or a file), on the
// report's cloth; and the observed order of every built-in tableau on the single spring of Chapter 2.
#include "program/command_line.hpp"
#include "analysis/fastest_modes.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "base/text.hpp"
#include "model/report_cases.hpp"
#include "model/single_spring.hpp"
#include "integrators/explicit_runge_kutta.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/limits.hpp"
#include "program/method_tables.hpp"
#include "program/output.hpp"
#include "program/progress.hpp"
#include "program/run_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// One run of the cloth with `tableau`, outputs in `dir`, plus lowest_point.dat (t, lowest z of the cloth) from
// the recorded frames. Returns report()'s exit status.
int run_cloth(const SceneParams& params, RunSettings run, const ButcherTableau& tableau, const std::string& source,
              const std::string& dir, const std::string& program) {
  const Scene scene(params);
  ForceField field(scene);
  ExplicitRungeKutta stepper(field, tableau);
  run.out_dir = dir;
  run.progress = terminal_progress(program);
  const double hc_start = run.dt * fastest_damping_rate(field, scene.initial_positions(), scene.initial_velocities());
  const RunResult result = simulate(stepper, run);
  const double hc_end = run.dt * fastest_damping_rate(field, result.x, result.v);
  {
    OutputFile file(dir + "/lowest_point.dat");
    std::fprintf(file.get(), "# t lowest_z (the lowest particle of the cloth, from frames.dat)\n");
    for (const Frame& f : result.frames) {
      double lowest = std::numeric_limits<double>::infinity();
      for (Eigen::Index k = 2; k < f.positions.size(); k += 3) lowest = std::min(lowest, f.positions[k]);
      std::fprintf(file.get(), "%.10g %.10g\n", f.t, lowest);
    }
    file.commit();
  }
  return finish_run(result, stepper, run, program,
                    {{"h_c_max_start", format_number(hc_start, 4)},
                     {"h_c_max_end", format_number(hc_end, 4)},
                     {"tableau", tableau.name},
                     {"tableau_source", source},
                     {"stages", std::to_string(tableau.stages())},
                     {"order", std::to_string(tableau.order)}});
}

// The report's three (K, D) of --report-runs, each in a subfolder named after the tableau: the name comes from
// the tableau file, so it is reduced to a safe file name first, and the folder can only ever be inside --out.
std::string report_folder(const ButcherTableau& tableau, const ReportCase& c) {
  return safe_file_name(tableau.name, 48, "tableau") + "_" + c.name();
}

// The files of one run of the cloth: the model page's four and the lowest particle's height (when `drawn`, for the
// chapter's figures).
OutputList single_run_outputs(const std::string& folder = "", bool drawn = false) {
  const OutputKind kind = drawn ? OutputKind::figure_input : OutputKind::data;
  OutputList files = drawn ? run_output_specs(folder, {"energy.dat"}) : run_output_specs(folder);
  files.push_back({(folder.empty() ? "" : folder + "/") + "lowest_point.dat", kind,
                   "the lowest particle's height at every frame"});
  return files;
}

// What --report-runs writes with `tableau`: order.dat, the page's table of methods (methods.md) and a folder of run
// outputs per report case; declared once (program/output_spec.hpp).
OutputList report_run_outputs(const ButcherTableau& tableau) {
  OutputList files = {{"order.dat", OutputKind::figure_input, "every tableau's error against h on the damped spring"},
                      {"methods.md", OutputKind::fragment, "the registry's explicit Runge-Kutta rows"}};
  for (const ReportCase& c : report_cases) files = files + single_run_outputs(report_folder(tableau, c), true);
  return files;
}

// The registry's explicit Runge-Kutta methods: "explicit_euler, heun, ...".
std::string tableau_names() {
  std::string names;
  for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta)) names += (names.empty() ? "" : ", ") + m->name;
  return names;
}

// Error at t = 1 s of every built-in tableau on the damped single spring (K = 50, D = 2, m = 1), against the
// closed form, for h = 0.1 / 2^k; writes order.dat (h, then one error column per tableau). The error is the
// largest deviation of a free particle's displacement or velocity (divided by omega) from the closed form.
void measure_orders(const std::string& dir) {
  const double K = 50, D = 2, m = 1, T = 1, s0 = -0.005;
  const Scene scene(single_spring_params(K, D));
  ForceField field(scene);
  const OscillatorState exact = single_spring_exact(K, D, m, s0, T);
  const double omega = std::sqrt(K / m);
  OutputFile file(dir + "/order.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# h");
  const std::vector<const Method*> tableaus = methods_of(MethodFamily::explicit_runge_kutta);
  for (const Method* m : tableaus) std::fprintf(out, " %s", m->name.c_str());
  std::fprintf(out, "\n");
  for (int k = 1; k <= 10; ++k) {
    const double h = 0.1 / std::pow(2.0, k);
    std::fprintf(out, "%.10g", h);
    for (const Method* m : tableaus) {
      // [observed_order]
      // One tableau at one step h: run to T, then the largest deviation from the closed form.
      ExplicitRungeKutta stepper(field, *m->tableau);
      Vector x, v;
      single_spring_initial_state(scene, s0, x, v);
      const Vector rest = scene.initial_positions();
      const auto steps = std::llround(T / h);
      for (long long n = 0; n < steps; ++n) stepper.step(h, x, v);
      double error = 0;
      for (Eigen::Index i = 1; i < x.size(); i += 3)
        error = std::max({error, std::abs(x[i] - rest[i] - exact.s), std::abs(v[i] - exact.ds) / omega});
      // [observed_order]
      std::fprintf(out, " %.6e", error);
    }
    std::fprintf(out, "\n");
  }
  file.commit();
}

}  // namespace

int main(int argc, char** argv) {
  std::string tableau_argument = "rk4";
  bool report_runs = false;
  CommandLine cli("ch03_runge_kutta",
                  "Chapter 3: an explicit Runge-Kutta method from its Butcher tableau on the report's cloth.");
  cli.add_value("--tableau", "NAME|FILE",
                "an explicit Runge-Kutta method of the registry (" + tableau_names() + "; default rk4) or a tableau file",
                [&](const std::string& s) { tableau_argument = s; });
  cli.add_switch("--report-runs",
                 "the chosen tableau on the report's (K, D) = (50,0), (200,0), (200,20), one subfolder of --out each, "
                 "order.dat and methods.md (the chapter's figures and table; exit 0 even when a run diverges)",
                 [&] { report_runs = true; });
  const auto chosen_tableau = [&] {
    try {
      return tableau_from_argument(tableau_argument);
    } catch (const InputError& e) {
      throw InputError(std::string("--tableau: ") + e.what());
    }
  };
  cli.declare_outputs([&](const Options&) { return report_runs ? report_run_outputs(chosen_tableau()) : single_run_outputs(); });
  return run_program(cli.program(), [&] {
    Options opt = cli.parse(argc, argv);
    const ButcherTableau tableau = chosen_tableau();
    const bool builtin = tableau.name == tableau_argument;
    const std::string source = builtin ? "builtin" : escaped(tableau_argument);
    const OutputList report_outputs = report_run_outputs(tableau);
    // What an earlier run of another mode or another built-in tableau left: removed, so that --out never mixes
    // two runs. A tableau file's folders are named after the file's `name`, which this run cannot know: they stay.
    OutputList stale = single_run_outputs();
    for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta)) stale = stale + report_run_outputs(*m->tableau);
    if (!report_runs) {
      prepare_declared_outputs(opt.run.out_dir, single_run_outputs(), stale);
      return run_cloth(opt.scene, opt.run, tableau, source, opt.run.out_dir, cli.program());
    }

    // A frame per step (up to --frames' largest value), for lowest_point.dat: the frames are then set by --t-end /
    // --dt, and checked as such, with the values each run uses, before the first one starts.
    opt.run.frames = static_cast<int>(std::min<long long>(step_count(opt.run), 100000));
    require_run_memory(opt.scene, opt.run, explicit_bytes_per_particle(), "--t-end");
    for (const ReportCase& c : report_cases) {
      const SceneParams p = with_case(opt.scene, c);
      require_representable(p, opt.run);
    }
    prepare_declared_outputs(opt.run.out_dir, report_outputs, stale);
    for (const ReportCase& c : report_cases) {
      const SceneParams p = with_case(opt.scene, c);
      // A divergence is a result here; an interruption ends the program (the interrupted run said so).
      if (const int status = run_cloth(p, opt.run, tableau, source, opt.run.out_dir + "/" + report_folder(tableau, c),
                                       cli.program());
          status >= 128)
        return status;
    }
    measure_orders(opt.run.out_dir);
    // The page's table of the registry's explicit Runge-Kutta rows: computed from their tableaus, not measured.
    write_text_fragment(opt.run.out_dir + "/methods.md", explicit_method_table().markdown());
    return 0;
  });
}
