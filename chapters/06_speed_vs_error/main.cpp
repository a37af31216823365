// Chapter 6: speed against error. Micro-benchmarks of the core, where the scene is hard (springs near zero
// length, sensitivity to perturbations), a reference solution with its credentials, work-precision diagrams on
// three configurations, and the cost of a step against the grid size. --quick is the reduced sweep the plots
// target runs; without it the full sweep runs.
#include "benchmarks.hpp"
#include "studies.hpp"

#include "program/command_line.hpp"

#include <cstdio>

using namespace cloth;

int main(int argc, char** argv) {
  CommandLine cli("ch06_speed_vs_error",
                  "Chapter 6: speed against error. Benchmarks, reference, work-precision diagrams, scaling.\n"
                  "--K and --damping are set per configuration; the other scene flags apply to all runs.");
  bool quick = false;
  bool bench_only = false;
  cli.add_switch("--quick", "a reduced sweep for the plots target (well under a minute)", [&] { quick = true; });
  cli.add_switch("--bench-only", "only the micro-benchmarks", [&] { bench_only = true; });
  return run_program(cli.program(), [&] {
    Options opt = cli.parse(argc, argv);
    prepare_output_dir(opt.run.out_dir);
    const std::string dir = opt.run.out_dir;

    const auto bench = ch06::run_benchmarks(opt.scene, quick ? 5 : 9);
    {
      std::FILE* out = std::fopen((dir + "/benchmarks.dat").c_str(), "w");
      std::fprintf(out, "# quantity wall_us cpu_us count count_unit  (grid %dx%d, K %g, D %g, folded states from t = 0.5 s)\n",
                   opt.scene.grid.M, opt.scene.grid.N, opt.scene.stiffness, opt.scene.damping);
      for (const auto& b : bench) {
        std::printf("  %-36s %10.2f us wall %10.2f us cpu  %g %s\n", b.name.c_str(), b.microseconds,
                    b.cpu_microseconds, b.count, b.count_name.c_str());
        std::fprintf(out, "%s %.4g %.4g %g %s\n", b.name.c_str(), b.microseconds, b.cpu_microseconds, b.count,
                     b.count_name.empty() ? "-" : b.count_name.c_str());
      }
      std::fclose(out);
    }
    if (bench_only) return 0;

    ch06::Sink sink{dir, std::fopen((dir + "/speed_vs_error.dat").c_str(), "w")};
    std::fprintf(sink.table,
                 "section config method h steps seconds err_max_T err_rms rhs_evaluations assemblies factorizations "
                 "cg_iterations newton_iterations status\n");
    for (const auto& b : bench)
      std::fprintf(sink.table, "benchmark %dx%d %s - - %.6e - - - - - - - ok\n", opt.scene.grid.M, opt.scene.grid.N,
                   b.name.c_str(), 1e-6 * b.microseconds);

    // [configs]
    // The horizons: before the sensitivity of (200, 20) explodes (t ~ 0.6 s) and before the first spring of
    // (50, 0) passes near zero length, so that the reference is trustworthy (see the page).
    const std::vector<ch06::Config> configs = {
        {"K50_D0", 50, 0, 0.25}, {"K200_D20", 200, 20, 0.25}, {"K5000_D20", 5000, 20, 0.25}};
    // [configs]
    ch06::near_zero_springs(opt.scene, 1.0, quick ? 5e-4 : 5e-5, sink);
    for (const double h : {2e-3, 1e-3, 5e-4, 2.5e-4}) ch06::local_error_along_trajectory(opt.scene, 1.0, h, sink);
    ch06::observed_orders(opt.scene, {0.25, 1.0}, 6, quick ? 11 : 15, sink);
    ch06::sensitivity(opt.scene, configs, quick ? 5e-4 : 5e-5, sink);

    const int samples = 16;
    for (const ch06::Config& c : configs) {
      double agreement = 0;
      const ch06::Trajectory ref = ch06::reference(opt.scene, c, samples, quick ? 12 : 15, sink, agreement);
      ch06::work_precision(opt.scene, c, ref, samples, 4, quick ? 10 : 16, quick ? 0.1 : 4.0, 5, agreement, sink);
    }
    ch06::scaling(opt.scene, quick ? std::vector<int>{20, 40} : std::vector<int>{20, 40, 80, 160, 320},
                  quick ? 3 : 5, quick ? 1.0 : 2.0, sink);
    std::fclose(sink.table);
    return 0;
  });
}
