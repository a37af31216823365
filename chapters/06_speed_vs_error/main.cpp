// Chapter 6: speed against error. Micro-benchmarks of the core, where the scene is hard (springs near zero
// length, sensitivity to perturbations), a reference solution with its credentials, work-precision diagrams on
// three configurations, and the cost of a step against the grid size. --quick is the reduced sweep the plots
// target runs; without it the full sweep runs.
#include "benchmarks.hpp"
#include "fragments.hpp"
#include "studies.hpp"

#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"

#include <cstdio>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// [configs]
// The horizons: before the sensitivity of (200, 20) explodes (t ~ 0.6 s) and before the first spring of
// (50, 0) passes near zero length, so that the reference is trustworthy (see the page).
const std::vector<ch06::Config> configs = {
    {"K50_D0", 50, 0, 0.25}, {"K200_D20", 200, 20, 0.25}, {"K5000_D20", 5000, 20, 0.25}};
// [configs]
const std::vector<double> local_error_steps = {2e-3, 1e-3, 5e-4, 2.5e-4};

// The files the program writes into --out: the micro-benchmarks' alone, or every study's; the page's fragments
// (fragments.hpp) among them.
std::vector<std::string> output_names(bool bench_only) {
  std::vector<std::string> names = {"benchmarks.dat"};
  for (const std::string& f : ch06::benchmark_fragment_names()) names.push_back(f);
  if (bench_only) return names;
  names.insert(names.end(), {"speed_vs_error.dat", "near_zero.dat", "orders.dat", "sensitivity.dat", "scaling.dat"});
  for (const double h : local_error_steps) names.push_back(ch06::local_error_name(h));
  for (const ch06::Config& c : configs) names.push_back("wp_" + c.name + ".dat");
  for (const std::string& f : ch06::study_fragment_names()) names.push_back(f);
  return names;
}

void write_benchmarks(const std::string& dir, const SceneParams& scene, const std::vector<ch06::Benchmark>& bench) {
  OutputFile file(dir + "/benchmarks.dat");
  std::fprintf(file.get(), "# quantity wall_us cpu_us count count_unit  (grid %dx%d, K %g, D %g, folded states from t = 0.5 s)\n",
               scene.grid.M, scene.grid.N, scene.stiffness, scene.damping);
  for (const auto& b : bench) {
    std::printf("  %-36s %10.2f us wall %10.2f us cpu  %g %s\n", b.name.c_str(), b.microseconds, b.cpu_microseconds,
                b.count, b.count_name.c_str());
    std::fprintf(file.get(), "%s %.4g %.4g %g %s\n", b.name.c_str(), b.microseconds, b.cpu_microseconds, b.count,
                 b.count_name.empty() ? "-" : b.count_name.c_str());
  }
  file.commit();
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch06_speed_vs_error",
                  "Chapter 6: speed against error. Benchmarks, reference, work-precision diagrams, scaling.\n"
                  "The scene flags shape every cloth; --K and --damping set the one of the benchmarks and of the\n"
                  "order studies, while the work-precision configurations set their own.");
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--K-flexion", "--damping", "--damping-model", "--springs",
                  "--pins", "--v0", "--out"});
  bool quick = false;
  bool bench_only = false;
  cli.add_switch("--quick", "a reduced sweep for the plots target (well under a minute)", [&] { quick = true; });
  cli.add_switch("--bench-only", "only the micro-benchmarks", [&] { bench_only = true; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    // The largest cloth held at once: the implicit rows' Newton matrices and factors on the --grid cloth.
    const long long particles = static_cast<long long>(opt.scene.grid.M) * opt.scene.grid.N;
    require_memory(static_cast<double>(particles) * implicit_bytes_per_particle(particles), "--grid",
                   "a run of the implicit methods on a " + std::to_string(opt.scene.grid.M) + "x" +
                       std::to_string(opt.scene.grid.N) + " grid",
                   ": expected a smaller grid");
    std::vector<std::string> others = output_names(false);
    prepare_outputs(opt.run.out_dir, output_names(bench_only), others);
    const std::string dir = opt.run.out_dir;
    const std::string command = reader_command(argc, argv);

    const auto bench = ch06::run_benchmarks(opt.scene, quick ? 5 : 9);
    write_benchmarks(dir, opt.scene, bench);
    ch06::write_benchmark_fragments(dir, bench, command);
    if (bench_only) return 0;

    OutputFile table(dir + "/speed_vs_error.dat");
    const ch06::Sink sink{dir, table.get()};
    std::fprintf(sink.table,
                 "section config method h steps seconds err_max_T err_rms rhs_evaluations assemblies factorizations "
                 "cg_iterations newton_iterations status\n");
    for (const auto& b : bench)
      std::fprintf(sink.table, "benchmark %dx%d %s - - %.6e - - - - - - - ok\n", opt.scene.grid.M, opt.scene.grid.N,
                   b.name.c_str(), 1e-6 * b.microseconds);

    ch06::StudyResults results;
    results.near_zero = ch06::near_zero_springs(opt.scene, 1.0, quick ? 5e-4 : 5e-5, sink);
    for (const double h : local_error_steps)
      results.local_errors.push_back(ch06::local_error_along_trajectory(opt.scene, 1.0, h, sink));
    results.orders = ch06::observed_orders(opt.scene, {0.25, 1.0}, 6, quick ? 11 : 15, sink);
    results.sensitivity = ch06::sensitivity(opt.scene, configs, quick ? 5e-4 : 5e-5, sink);

    const int samples = 16;
    for (const ch06::Config& c : configs) {
      ch06::ReferenceCheck& check = results.references.emplace_back();
      const ch06::Trajectory ref = ch06::reference(opt.scene, c, samples, quick ? 12 : 15, sink, check);
      const auto points = ch06::work_precision(opt.scene, c, ref, samples, 4, quick ? 10 : 16, quick ? 0.1 : 4.0, 5,
                                               check.agreement, sink);
      results.work.insert(results.work.end(), points.begin(), points.end());
    }
    const std::vector<int> sizes = quick ? std::vector<int>{20, 40} : std::vector<int>{20, 40, 80, 160, 320};
    results.scaling = ch06::scaling(opt.scene, sizes, quick ? 3 : 5, quick ? 1.0 : 2.0, sink);
    table.commit();
    ch06::write_study_fragments(dir, results, configs, command);
    return 0;
  });
}
