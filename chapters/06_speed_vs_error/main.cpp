// Chapter 6: speed against error. Micro-benchmarks of the core, a trustworthy reference solution,
// work-precision diagrams, and the cost of a step against the grid size.
#include "benchmarks.hpp"

#include "cloth/command_line.hpp"

#include <cstdio>

using namespace cloth;

int main(int argc, char** argv) {
  CommandLine cli("ch06_speed_vs_error",
                  "Chapter 6: speed against error. Benchmarks, reference, work-precision diagrams, scaling.");
  bool quick = false;
  bool bench_only = false;
  cli.add_switch("--quick", "a reduced sweep for the plots target (under a minute)", [&] { quick = true; });
  cli.add_switch("--bench-only", "only the micro-benchmarks", [&] { bench_only = true; });
  return run_program(cli.program(), [&] {
    Options opt = cli.parse(argc, argv);
    prepare_output_dir(opt.run.out_dir);
    const auto bench = ch06::run_benchmarks(opt.scene, quick ? 5 : 9);
    std::FILE* out = std::fopen((opt.run.out_dir + "/benchmarks.dat").c_str(), "w");
    std::fprintf(out, "# quantity wall_us cpu_us count count_unit  (grid %dx%d, K %g, D %g, folded state t = 0.5 s)\n",
                 opt.scene.grid.M, opt.scene.grid.N, opt.scene.stiffness, opt.scene.damping);
    for (const auto& b : bench) {
      std::printf("  %-36s %10.2f us wall %10.2f us cpu  %g %s\n", b.name.c_str(), b.microseconds,
                  b.cpu_microseconds, b.count, b.count_name.c_str());
      std::fprintf(out, "%s %.4g %.4g %g %s\n", b.name.c_str(), b.microseconds, b.cpu_microseconds, b.count,
                   b.count_name.empty() ? "-" : b.count_name.c_str());
    }
    std::fclose(out);
    (void)bench_only;
    return 0;
  });
}
