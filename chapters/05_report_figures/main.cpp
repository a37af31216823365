// Chapter 5: the report's comparison regenerated. Runs explicit Euler, symplectic Euler, RK4 and implicit Euler on
// the report scene at its three (K, D), then sweeps K x D per method, and writes the data of the chapter's figures
// (strain-coloured meshes, energy, sag, animations, heat maps) and their summary tables. The experiments are in
// experiments.hpp; the figures are drawn by plot.gp from the data files alone.
#include "experiments.hpp"

#include "base/input_error.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

using namespace cloth;

int main(int argc, char** argv) {
  CommandLine cli("ch05_report_figures",
                  "Chapter 5: the report's comparison. Runs explicit Euler, symplectic Euler, RK4 and implicit Euler\n"
                  "at (K, D) = (50, 0), (200, 0), (200, 20), and sweeps K in {10..1000} x D in {0, 1, 5, 20}.\n"
                  "The chapter sets K, D and the frames itself; the other scene flags shape every run. Figure data go\n"
                  "to --out.");
  cli.use_common({"--grid", "--spacing", "--mass", "--K-flexion", "--damping-model", "--springs", "--pins", "--v0",
                  "--dt", "--t-end", "--out"});
  ch05::Settings settings;
  cli.add_value("--threads", "n", "runs in parallel, 1..64 [2]", [&](const std::string& s) {
    const long long n = parse_integer(s);
    if (n < 1 || n > 64) throw InputError("expected an integer from 1 to 64, got '" + s + "'");
    settings.threads = static_cast<int>(n);
  });
  cli.add_value("--sweep-t-end-implicit", "T", "simulated time of implicit Euler's sweep runs [s] [same as --t-end]",
                [&](const std::string& s) {
                  settings.sweep_t_end_implicit = parse_number(s);
                  if (settings.sweep_t_end_implicit <= 0) throw InputError("expected a positive time, got '" + s + "'");
                });
  cli.add_switch("--no-sweep", "skip the K x D sweep", [&] { settings.sweep = false; });
  cli.declare_outputs([&](const Options&) { return ch05::outputs(settings.sweep); });

  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    settings.command = reader_command(argc, argv);
    if (settings.sweep_t_end_implicit > opt.run.t_end) throw InputError("--sweep-t-end-implicit: must not exceed --t-end");
    if (settings.sweep_t_end_implicit == 0) settings.sweep_t_end_implicit = opt.run.t_end;
    ch05::require_memory_of_runs(opt, settings);
    prepare_declared_outputs(opt.run.out_dir, ch05::outputs(settings.sweep), ch05::outputs(true));

    const std::vector<ch05::Run> runs = ch05::run_all(opt, settings);
    // Every run has the same E(0): K and D do not enter the launch.
    const ch05::EnergyReference reference =
        ch05::energy_reference(opt.scene, runs.front().result.energy.front().energy.total());
    ch05::write_figure_data(runs, opt, settings, reference);
    ch05::write_theory(runs, opt, settings);
    ch05::write_growth(runs, opt, settings, reference);
    if (settings.sweep) ch05::write_sweep(runs, opt, settings, reference);
    return 0;
  });
}
