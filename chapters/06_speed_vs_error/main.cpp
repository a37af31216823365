// Chapter 6: speed against error. The outline of the page: what the core's pieces cost, where the scene is hard
// (springs near zero length, the order they cost, sensitivity), a reference with its credentials, the
// work-precision sweep on three cloths, and the cost of a step against the grid size. --quick is the reduced
// sweep the book's build runs; without it the full sweep runs.
#include "benchmarks.hpp"
#include "studies.hpp"

#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"

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

// The files the program writes into --out, in one list: the micro-benchmarks' (all that --bench-only writes),
// then every study's data and the page's fragments.
const std::vector<std::string> benchmark_outputs = {"benchmarks.dat", "benchmarks.md", "factorizations.md",
                                                    "factorization_speedup.md"};
std::vector<std::string> study_outputs() {
  std::vector<std::string> names = {
      "speed_vs_error.dat", "near_zero.dat", "orders.dat", "sensitivity.dat", "scaling.dat",
      "near_zero.md", "local_error.md", "jumps.md", "observed_orders.md", "sensitivity.md", "reference.md",
      "fastest.md", "fastest_summary.md", "dropped.md", "effective_orders.md", "implicit_variants.md",
      "stiff_pick.md", "scaling.md"};
  for (const double h : local_error_steps) names.push_back(ch06::local_error_name(h));
  for (const ch06::Config& c : configs) names.push_back("wp_" + c.name + ".dat");
  names.insert(names.end(), benchmark_outputs.begin(), benchmark_outputs.end());
  return names;
}

void write_benchmarks(const std::string& dir, const SceneParams& scene, const std::vector<ch06::Benchmark>& bench) {
  OutputFile file(dir + "/benchmarks.dat");
  std::fprintf(file.get(), "# quantity wall_us cpu_us count count_unit  (grid %dx%d, K %g, D %g, folded states "
               "from t = 0.5 s; medians)\n", scene.grid.M, scene.grid.N, scene.stiffness, scene.damping);
  for (const auto& b : bench)
    std::fprintf(file.get(), "%s %.4g %.4g %g %s\n", b.name.c_str(), b.microseconds, b.cpu_microseconds, b.count,
                 b.count_name.empty() ? "-" : b.count_name.c_str());
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
  bool quick = false, bench_only = false;
  cli.add_switch("--quick", "a reduced sweep for the plots target (well under a minute)", [&] { quick = true; });
  cli.add_switch("--bench-only", "only the micro-benchmarks", [&] { bench_only = true; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const SceneParams& scene = opt.scene;
    // The largest cloth held at once: the implicit rows' Newton matrices and factors on the --grid cloth.
    const long long particles = static_cast<long long>(scene.grid.M) * scene.grid.N;
    require_memory(static_cast<double>(particles) * implicit_bytes_per_particle(particles), "--grid",
                   "a run of the implicit methods on a " + std::to_string(scene.grid.M) + "x" +
                       std::to_string(scene.grid.N) + " grid", ": expected a smaller grid");
    prepare_outputs(opt.run.out_dir, bench_only ? benchmark_outputs : study_outputs(), study_outputs());
    const std::string dir = opt.run.out_dir, command = reader_command(argc, argv);

    // 1. What the core's pieces cost: a force evaluation, a factorization, a CG solve, a step.
    const auto bench = ch06::run_benchmarks(scene, quick ? 5 : 9);
    write_benchmarks(dir, scene, bench);
    ch06::write_benchmark_fragments(dir, bench, command);
    if (bench_only) return 0;
    OutputFile table(dir + "/speed_vs_error.dat");
    const ch06::Sink sink{dir, table.get()};
    std::fprintf(sink.table, "section config method h steps seconds err_max_T err_rms rhs_evaluations assemblies "
                             "factorizations cg_iterations newton_iterations status\n");

    // 2. Where the scene is hard: springs near zero length, the order they cost, and sensitivity.
    const double fine = quick ? 5e-4 : 5e-5;
    ch06::write_near_zero_fragment(dir, ch06::near_zero_springs(scene, 1.0, fine, sink));
    std::vector<ch06::LocalError> local_errors;
    for (const double h : local_error_steps) local_errors.push_back(ch06::local_error_along_trajectory(scene, 1.0, h, sink));
    const auto orders = ch06::observed_orders(scene, {0.25, 1.0}, 6, quick ? 11 : 15, sink);
    ch06::write_order_loss_fragments(dir, local_errors, orders, command);
    ch06::write_sensitivity_fragment(dir, ch06::sensitivity(scene, configs, fine, sink), configs, command);

    // 3. A reference with its credentials, then every method against it on each cloth.
    const ch06::SweepPlan plan{16, 4, quick ? 10 : 16, 2, 10, quick ? 0.1 : 4.0, 5};
    std::vector<ch06::ReferenceCheck> references;
    std::vector<ch06::WorkPoint> work;
    for (const ch06::Config& c : configs) {
      ch06::ReferenceCheck& check = references.emplace_back();
      const ch06::Trajectory ref = ch06::reference(scene, c, plan.samples, quick ? 12 : 15, sink, check);
      const auto points = ch06::work_precision(scene, c, ref, check.agreement, plan, sink);
      work.insert(work.end(), points.begin(), points.end());
    }
    ch06::write_sweep_fragments(dir, references, work, configs, command);

    // 4. The cost of a step against the grid size.
    const ch06::ScalingPlan growth{quick ? std::vector<int>{20, 40} : std::vector<int>{20, 40, 80, 160, 320},
                                   quick ? 3 : 5, quick ? 1.0 : 2.0};
    ch06::write_scaling_fragment(dir, ch06::scaling(scene, growth, sink), command);
    table.commit();
    return 0;
  });
}
