// Chapter 2: explicit Euler on the report's cloth, symplectic Euler beside it, and the measurement of explicit
// Euler's energy growth factor (1 + (h omega)^2) per step on an undamped spring.
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "analysis/fastest_modes.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "model/report_cases.hpp"
#include "model/single_spring.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/interrupt.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"
#include "program/progress.hpp"
#include "program/run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// The chapter's two methods, registry names.
const std::vector<std::string> chapter_methods = {"explicit_euler", "symplectic_euler"};

/// One undamped spring's energy under explicit and symplectic Euler, after every step.
struct SpringEnergies {
  double omega = 0, h = 0, E0 = 0;
  std::vector<double> explicit_euler, symplectic_euler;  ///< E_n for n = 1, 2, ... (fewer when interrupted)
};

// [single_spring_measurement]
// Runs the single spring of single_spring.hpp with explicit and symplectic Euler from the same stretched state and
// records both energies after every step; explicit Euler's should be E0 (1 + (h omega)^2)^n exactly.
SpringEnergies single_spring_energies(const SceneParams& params, const RunSettings& run) {
  const Scene scene(params);
  ForceField field(scene);
  auto euler = make_stepper("explicit_euler", field);
  auto symplectic = make_stepper("symplectic_euler", field);
  // Stretched by 1% of the rest length: even after the growth below the spring stays shorter than twice its rest
  // length and longer than zero, where the force is exactly linear.
  const double s0 = -0.01 * params.grid.d;
  Vector xe, ve, xs, vs;
  single_spring_initial_state(scene, s0, xe, ve);
  single_spring_initial_state(scene, s0, xs, vs);
  SpringEnergies e;
  e.omega = std::sqrt(params.stiffness / params.mass);
  e.h = run.dt;
  e.E0 = field.energy(xe, ve).total();
  const auto steps = static_cast<std::size_t>(std::llround(run.t_end / run.dt));
  e.explicit_euler.reserve(steps);
  e.symplectic_euler.reserve(steps);
  for (std::size_t n = 1; n <= steps && interrupt_signal() == 0; ++n) {
    euler->step(e.h, xe, ve);
    symplectic->step(e.h, xs, vs);
    e.explicit_euler.push_back(field.energy(xe, ve).total());
    e.symplectic_euler.push_back(field.energy(xs, vs).total());
  }
  return e;
}
// [single_spring_measurement]

// Writes single_spring.dat (t, explicit Euler's energy, the prediction E0 (1 + (h omega)^2)^n, symplectic Euler's
// energy) and prints the measured per-step factor of explicit Euler, (E_n / E_0)^(1/n), which it returns.
double measure_single_spring(const SceneParams& params, const RunSettings& run, const std::string& dir) {
  const SpringEnergies e = single_spring_energies(params, run);
  const double predicted = 1 + (e.h * e.omega) * (e.h * e.omega);
  OutputFile file(dir + "/single_spring.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# single undamped spring, K = %g N/m, m = %g kg, omega = %.10g rad/s, h = %g s, h omega = %.6g\n",
               params.stiffness, params.mass, e.omega, e.h, e.h * e.omega);
  std::fprintf(out, "# t E_explicit_euler E0*(1+(h omega)^2)^n E_symplectic_euler\n");
  std::fprintf(out, "%.10g %.17g %.17g %.17g\n", 0.0, e.E0, e.E0, e.E0);
  for (std::size_t k = 0; k < e.explicit_euler.size(); ++k) {
    const auto n = static_cast<double>(k + 1);
    std::fprintf(out, "%.10g %.17g %.17g %.17g\n", n * e.h, e.explicit_euler[k], e.E0 * std::pow(predicted, n),
                 e.symplectic_euler[k]);
  }
  file.commit();
  throw_if_interrupted();  // single_spring.dat is whole up to the last step taken
  const auto steps = static_cast<long long>(e.explicit_euler.size());
  const double measured = std::pow(e.explicit_euler.back() / e.E0, 1.0 / static_cast<double>(steps));
  std::printf("single spring: K = %g N/m, m = %g kg, omega = %.6g rad/s, h = %g s, h omega = %.6g\n", params.stiffness,
              params.mass, e.omega, e.h, e.h * e.omega);
  std::printf("  energy growth per explicit Euler step: predicted 1 + (h omega)^2 = %.15f, measured over %lld steps "
              "%.15f\n", predicted, steps, measured);
  return measured;
}

// The report's three (K, D) (model/report_cases.hpp), run with both methods by --report-runs, each in its own
// subfolder.
std::string report_folder(const std::string& method, const ReportCase& c) { return method + "_" + c.name(); }

// The files each mode writes into --out, declared once (program/output_spec.hpp): so that the folder is checked
// before anything runs and the files of another mode, left by an earlier run, are removed.
OutputList outputs_of(bool single_spring, bool report_runs) {
  const OutputSpec spring = {"single_spring.dat", OutputKind::figure_input,
                             "explicit Euler's energy on one undamped spring against (1 + (h omega)^2)^n"};
  if (single_spring) return {spring};
  if (!report_runs) return run_output_specs();
  OutputList files = {spring, {"report_runs.md", OutputKind::fragment, "how each method's run of each (K, D) ended"}};
  for (const std::string& m : chapter_methods)
    for (const ReportCase& c : report_cases) files = files + run_output_specs(report_folder(m, c), {"energy.dat"});
  return files;
}

// How a run of the report scene ended, as a cell of the page's table: "finishes; E(2 s) = 2.41e+07 J, 304 times
// E(0)" or "diverges at step 90, t = 0.9 s".
std::string outcome_cell(const RunResult& r) {
  if (r.status != RunStatus::ok)
    return std::string(r.status == RunStatus::diverged ? "diverges" : run_status_name(r.status)) + " at step " +
           std::to_string(r.failed_step) + ", t = " + format_number(r.failed_t, 3) + " s";
  const double e0 = r.energy.front().energy.total(), e1 = r.energy.back().energy.total();
  const double ratio = e1 / e0;
  const std::string energy = std::abs(e1) < 1e6 ? std::to_string(std::lround(e1)) : format_number(e1, 3);
  const std::string change = std::abs(ratio - 1) >= 0.1 ? format_number(ratio, 3) + " times E(0)"
                             : format_number(100 * std::abs(ratio - 1), 2) + (ratio > 1 ? "% above E(0)" : "% below E(0)");
  return "finishes; E(" + format_number(r.t, 3) + " s) = " + energy + " J, " + change;
}

// One run of the report scene with `method`, outputs in `dir`; returns report()'s exit status, and how the run
// ended in `outcome` when it is given.
int run_cloth(const SceneParams& params, RunSettings run, const std::string& method, const std::string& dir,
              const std::string& program, std::string* outcome = nullptr) {
  const Scene scene(params);
  ForceField field(scene);
  auto stepper = make_stepper(method, field);
  run.out_dir = dir;
  const double omega_max = fastest_rest_frequency(field);
  const double hw = run.dt * omega_max;
  const double hc_start = run.dt * fastest_damping_rate(field, scene.initial_positions(), scene.initial_velocities());
  run.progress = terminal_progress(program);
  const RunResult result = simulate(*stepper, run);
  const double hc_end = run.dt * fastest_damping_rate(field, result.x, result.v);
  if (outcome != nullptr) *outcome = outcome_cell(result);
  std::printf("%s: K = %g, D = %g: fastest mode at rest omega_max = %.4g rad/s, h omega_max = %.4g, explicit Euler "
              "multiplies its energy by %.4g per step\n", program.c_str(), params.stiffness, params.damping, omega_max,
              hw, 1 + hw * hw);
  return finish_run(result, *stepper, run, program,
                    {{"omega_max_at_rest", format_number(omega_max)},
                     {"h_omega_max", format_number(hw)},
                     {"explicit_euler_growth_per_step", format_number(1 + hw * hw, 10)},
                     {"h_c_max_start", format_number(hc_start, 4)},
                     {"h_c_max_end", format_number(hc_end, 4)}});
}

}  // namespace

int main(int argc, char** argv) {
  std::string method = "explicit_euler";
  bool single_spring = false, report_runs = false;
  CommandLine cli("ch02_explicit_euler",
                  "Chapter 2: explicit Euler (or symplectic Euler) on the report's cloth, and explicit Euler's energy\n"
                  "growth factor measured on a single undamped spring.");
  cli.add_value("--method", "explicit_euler|symplectic_euler", "explicit Euler (default) or symplectic Euler",
                [&](const std::string& s) {
                  if (std::find(chapter_methods.begin(), chapter_methods.end(), s) == chapter_methods.end())
                    throw InputError("unknown method '" + s + "': expected explicit_euler or symplectic_euler");
                  method = s;
                });
  cli.add_switch("--single-spring",
                 "instead of the cloth, one undamped spring (K, --dt, --t-end apply): energy growth, single_spring.dat",
                 [&] { single_spring = true; });
  cli.add_switch("--report-runs",
                 "the report's (K, D) = (50,0), (200,0), (200,20) with both methods and the single spring at K = 200, "
                 "one subfolder of --out each (the chapter's figures; exit 0 even when a run diverges)",
                 [&] { report_runs = true; });
  cli.declare_outputs([&](const Options&) { return outputs_of(single_spring, report_runs); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    if (single_spring && report_runs) throw InputError("--single-spring and --report-runs: choose one");
    if (single_spring && opt.scene.damping != 0)
      throw InputError("--single-spring: the growth factor is for D = 0; drop --damping");
    // Every run of --report-runs is checked with the values it uses, before the first one starts.
    if (report_runs)
      for (const ReportCase& c : report_cases) require_representable(with_case(opt.scene, c), opt.run);
    prepare_declared_outputs(opt.run.out_dir, outputs_of(single_spring, report_runs),
                    outputs_of(false, false) + outputs_of(false, true));  // what any mode writes
    if (single_spring) {
      measure_single_spring(single_spring_params(opt.scene.stiffness, 0), opt.run, opt.run.out_dir);
      return 0;
    }
    if (!report_runs) return run_cloth(opt.scene, opt.run, method, opt.run.out_dir, cli.program());

    // The page's table: one row per method, one column per report case.
    std::vector<std::string> header = {"method"};
    for (const ReportCase& c : report_cases) header.push_back("K = " + format_number(c.K) + ", D = " + format_number(c.D));
    MarkdownTable table(header);
    for (const std::string& m : chapter_methods) {
      std::vector<std::string> row = {find_method(m).title};
      for (const ReportCase& c : report_cases) {
        const SceneParams p = with_case(opt.scene, c);
        std::string outcome;
        // A divergence is a result here; an interruption ends the program (the interrupted run said so).
        if (const int status =
                run_cloth(p, opt.run, m, opt.run.out_dir + "/" + report_folder(m, c), cli.program(), &outcome);
            status >= 128)
          return status;
        row.push_back(outcome);
      }
      table.add_row(row);
    }
    write_table_fragment(opt.run.out_dir + "/report_runs.md", table, reader_command(argc, argv));
    measure_single_spring(single_spring_params(200, 0), opt.run, opt.run.out_dir);
    return 0;
  });
}
