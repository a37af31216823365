// Chapter 7: when is each method stable? Draws every method's stability region from its tableau, the cloth's
// spectrum over it, predicts the largest stable step h_max from the two, and measures h_max by bisection on the
// report scene over a log grid of K, for D = 0 and D = 20. Each experiment is a function of its own file:
// stability_regions.cpp, cloth_spectrum.cpp, hmax.cpp.
#include "cloth_spectrum.hpp"
#include "hmax.hpp"
#include "stability_regions.hpp"

#include "base/input_error.hpp"
#include "model/report_cases.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"
#include "program/output_kinds.hpp"
#include "program/timing.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace ch07;

namespace {

// The files the program writes into --out, declared once (program/output_spec.hpp).
cloth::OutputList outputs() {
  using cloth::OutputKind;
  using namespace cloth::output_kinds;
  cloth::OutputList files = {
      {"regions.dat", figure, "|R(z)| over the complex plane, every tableau"},
      {"predicted_rest.dat", figure, "h_max predicted from the rest spectrum against K"},
      {"predicted.dat", figure, "h_max predicted at rest and at the sagged equilibrium, per K and D"},
      {"measured.dat", figure, "h_max measured by bisection, with its bracket"},
      {"summary.txt", data, "the headline numbers, key = value"},
      {"implicit_euler.txt", fragment, "implicit Euler's probe runs at h = 0.1 s"},
      {"spectra.txt", fragment, "the transcript of the spectra's largest eigenvalues"},
      {"grid_summary.md", fragment, "the grid's fastest modes and reach, for the larger grid's section"},
      {"damped_reach.md", fragment, "how far the damped modes reach along the real axis"},
      {"hmax_table.md", fragment, "predicted against measured h_max"}};
  for (const cloth::ReportCase& c : cloth::report_cases)
    for (const char* state : {"rest", "sagged"})
      files.push_back({std::string("spectrum_") + state + "_" + c.name() + ".dat", figure,
                       std::string("h lambda of the ") + state + " cloth, h = --dt"});
  files.push_back({"run_time.md", fragment, "how long the whole run took (written last)"});
  return files;
}

// What the sweep needs before anything runs: a cloth that hangs (its sagged equilibrium is what the predictions
// linearise about) and the memory of `threads` implicit runs on the grid at once.
void check_scene(const cloth::SceneParams& scene, int threads) {
  if (scene.pins == cloth::PinSet::none)
    throw cloth::InputError("--pins: none leaves the cloth falling forever, with no sagged equilibrium to linearise "
                            "about: expected corners, corner or edge");
  const long long particles = static_cast<long long>(scene.grid.M) * scene.grid.N;
  cloth::require_memory(threads * static_cast<double>(particles) * cloth::implicit_bytes_per_particle(particles),
                        "--grid",
                        std::to_string(threads) + " runs at once on a " + std::to_string(scene.grid.M) + "x" +
                            std::to_string(scene.grid.N) + " grid",
                        ": expected a smaller grid or fewer --threads");
}

SweepSettings sweep_settings(bool full, SweepSettings sweep, double T) {
  sweep.T = T;
  if (full) {
    sweep.methods.insert(sweep.methods.end(), {"kutta3", "midpoint", "rule38"});
    sweep.bisections = 7;
    sweep.run_budget = 0;
    sweep.dense_implicit = true;
  }
  const int per_decade = full ? 3 : 1;
  for (int k = 0; k <= 4 * per_decade; ++k) sweep.stiffnesses.push_back(std::pow(10.0, 1.0 + double(k) / per_decade));
  return sweep;
}

// run_time.md: how long the run took, from the start of main(), in wall-clock time and in processor time summed
// over its threads (program/timing.hpp), with the command that measured it.
void write_run_time(const std::string& dir, const std::string& command, double wall_started, double cpu_started,
                    int threads) {
  const double wall = cloth::wall_seconds() - wall_started;
  const double cpu = cloth::process_cpu_seconds() - cpu_started;
  cloth::write_text_fragment(dir + "/run_time.md",
                             "`" + command + "` took " + cloth::format_fixed(wall, 1) + " s of wall-clock time and " +
                                 cloth::format_fixed(cpu, 1) + " s of processor time on " + std::to_string(threads) +
                                 " threads.\n\n" + cloth::measured_by_line(command));
}

}  // namespace

int main(int argc, char** argv) {
  const double wall_started = cloth::wall_seconds(), cpu_started = cloth::process_cpu_seconds();
  cloth::CommandLine cli("ch07_stability",
                         "Chapter 7: stability regions from the Butcher tableaus, the cloth's spectrum over them, "
                         "predicted\nand measured largest stable steps h_max over K in [10, 1e5] and D in {0, 20}.");
  // K and D are the sweep's; the other scene flags shape every cloth, --dt is the h of the spectrum figure and
  // --t-end the horizon T of every run.
  cli.use_common({"--grid", "--spacing", "--mass", "--damping-model", "--springs", "--pins", "--v0", "--dt", "--t-end",
                  "--out"});
  bool full = false;
  SweepSettings settings;
  settings.run_budget = 5e7;
  cli.add_switch("--full", "full-resolution sweep: 13 values of K, 7 bisections, every tableau, no budget, and the "
                           "dense spectrum of the damped sagged cloth on grids up to 20 x 20 (several minutes)",
                 [&] { full = true; });
  cli.add_value("--threads", "N", "worker threads for the sweep (default 2)", [&](const std::string& s) {
    const long long n = cloth::parse_integer(s);
    if (n < 1 || n > 64) throw cloth::InputError("expected a whole number from 1 to 64");
    settings.threads = static_cast<int>(n);
  });
  cli.add_value("--budget", "N", "largest cost of one measuring run, in unknowns times right-hand sides (default "
                                 "5e7: every run on 20 x 20; 0: no limit)", [&](const std::string& s) {
    settings.run_budget = cloth::parse_number(s);
    if (settings.run_budget < 0) throw cloth::InputError("expected a number >= 0");
  });
  cli.declare_outputs([](const cloth::Options&) { return outputs(); });
  return cloth::run_program(cli.program(), [&] {
    const cloth::Options opt = cli.parse(argc, argv);
    check_scene(opt.scene, settings.threads);
    cloth::prepare_declared_outputs(opt.run.out_dir, outputs());
    const std::string& dir = opt.run.out_dir;
    const SweepSettings sweep = sweep_settings(full, settings, opt.run.t_end);
    try {
      auto summary = stability_regions(dir);                               // 1. the regions |R(z)| <= 1
      const RestSpectrum rest = rest_spectrum(opt.scene);                  // 2. the cloth's spectrum over them
      Equilibria equilibria(opt.scene);
      for (const auto& entry : report_spectra(dir, opt.scene, rest, equilibria, opt.run.dt, full, sweep.threads))
        summary.push_back(entry);
      write_rest_predictions(dir, rest, sweep, opt.scene.mass);            // 3. h_max predicted and measured
      const std::string command = cloth::reader_command(argc, argv);
      for (const auto& entry : hmax_sweep(dir, opt.scene, rest, equilibria, sweep, command)) summary.push_back(entry);
      cloth::write_key_values(dir + "/summary.txt", summary);
      write_run_time(dir, command, wall_started, cpu_started, sweep.threads);
    } catch (const NoEquilibrium& e) {
      std::fprintf(stderr, "%s: %s\n", cli.program().c_str(), e.what());
      return 3;
    }
    return 0;
  });
}
