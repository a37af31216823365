// Chapter 7: when is each method stable? Draws every method's stability region from its tableau, the cloth's
// spectrum over it, predicts the largest stable step h_max from the two, and measures h_max by bisection on the
// report scene over a log grid of K, for D = 0 and D = 20. Each experiment is a function of its own file:
// stability_regions.cpp, cloth_spectrum.cpp, hmax.cpp.
#include "cloth_spectrum.hpp"
#include "hmax.hpp"
#include "stability_regions.hpp"

#include "base/input_error.hpp"
#include "program/command_line.hpp"
#include "program/output.hpp"

#include <cmath>

using namespace ch07;

int main(int argc, char** argv) {
  cloth::CommandLine cli("ch07_stability",
                         "Chapter 7: stability regions from the Butcher tableaus, the cloth's spectrum over them, "
                         "predicted\nand measured largest stable steps h_max over K in [10, 1e5] and D in {0, 20}.");
  // K and D are the sweep's; the other scene flags shape every cloth, --dt is the h of the spectrum figure and
  // --t-end the horizon T of every run.
  cli.use_common({"--grid", "--spacing", "--mass", "--damping-model", "--springs", "--pins", "--v0", "--dt", "--t-end",
                  "--out"});
  bool full = false;
  SweepSettings sweep;
  sweep.run_budget = 5e7;
  cli.add_switch("--full", "full-resolution sweep: 13 values of K, 7 bisections, every tableau, no budget, and the "
                           "dense spectrum of the damped sagged cloth on grids up to 20 x 20 (several minutes)",
                 [&] { full = true; });
  cli.add_value("--threads", "N", "worker threads for the sweep (default 2)", [&](const std::string& s) {
    const long long n = cloth::parse_integer(s);
    if (n < 1 || n > 64) throw cloth::InputError("expected a whole number from 1 to 64");
    sweep.threads = static_cast<int>(n);
  });
  cli.add_value("--budget", "N", "largest cost of one measuring run, in unknowns times right-hand sides (default "
                                 "5e7: every run on 20 x 20; 0: no limit)", [&](const std::string& s) {
    sweep.run_budget = cloth::parse_number(s);
    if (sweep.run_budget < 0) throw cloth::InputError("expected a number >= 0");
  });
  return cloth::run_program(cli.program(), [&] {
    const cloth::Options opt = cli.parse(argc, argv);
    cloth::prepare_output_dir(opt.run.out_dir);
    const std::string& dir = opt.run.out_dir;
    sweep.T = opt.run.t_end;
    if (full) {
      sweep.methods.insert(sweep.methods.end(), {"kutta3", "midpoint", "rule38"});
      sweep.bisections = 7;
      sweep.run_budget = 0;
      sweep.dense_implicit = true;
    }
    const int per_decade = full ? 3 : 1;
    for (int k = 0; k <= 4 * per_decade; ++k) sweep.stiffnesses.push_back(std::pow(10.0, 1.0 + double(k) / per_decade));

    auto summary = stability_regions(dir);                                 // 1. the regions |R(z)| <= 1
    const RestSpectrum rest = rest_spectrum(opt.scene);                    // 2. the cloth's spectrum over them
    Equilibria equilibria(opt.scene);
    for (const auto& entry : report_spectra(dir, opt.scene, rest, equilibria, opt.run.dt, full, sweep.threads)) summary.push_back(entry);
    write_rest_predictions(dir, rest, sweep, opt.scene.mass);              // 3. h_max predicted and measured
    for (const auto& entry : hmax_sweep(dir, opt.scene, rest, equilibria, sweep)) summary.push_back(entry);
    cloth::write_key_values(dir + "/summary.txt", summary);
    return 0;
  });
}
