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
#include "program/output_kinds.hpp"
#include "program/output_spec.hpp"

#include <string>
#include <vector>

using namespace cloth;

namespace {

// [configs]
// The horizons: before the sensitivity of (200, 20) explodes (t ~ 0.6 s) and before the first spring of
// (50, 0) passes near zero length, so that the reference is trustworthy (see the page).
const std::vector<ch06::Config> configs = {{.name = "K50_D0", .K = 50, .D = 0, .T = 0.25},
                                           {.name = "K200_D20", .K = 200, .D = 20, .T = 0.25},
                                           {.name = "K5000_D20", .K = 5000, .D = 20, .T = 0.25}};
// [configs]
const std::vector<double> local_error_steps = {2e-3, 1e-3, 5e-4, 2.5e-4};
// The horizon of the studies of where the scene is hard: T = 1 s, through the first folds and their jumps.
const double hard_horizon = 1.0;

// The files the program writes into --out, declared once (program/output_spec.hpp): the micro-benchmarks' (all
// that --bench-only writes), then every study's data and the page's fragments.
OutputList benchmark_outputs() {
  return {{"benchmarks.dat", OutputKind::figure_input, "every micro-benchmark: median wall and CPU time, count"},
          {"benchmarks.md", OutputKind::fragment, "the core's micro-benchmarks"},
          {"factorizations.md", OutputKind::fragment, "every factorization of the same Newton matrix"},
          {"factorization_speedup.md", OutputKind::fragment, "how much faster the block factorizations are"}};
}
OutputList study_outputs() {
  using namespace cloth::output_kinds;
  OutputList files = {
      {"speed_vs_error.dat", data, "every run of every study: step, time, errors, work counters"},
      {"near_zero.dat", figure, "the shortest spring's l / L0 over time"},
      {"orders.dat", figure, "step halvings: difference and observed order, per method and horizon"},
      {"sensitivity.dat", figure, "a perturbation's amplification over time, per configuration"},
      {"scaling.dat", figure, "the cost of a step against the grid size, per method"},
      {"near_zero.md", fragment, "when the shortest spring first comes near zero length"},
      {"local_error.md", fragment, "RK4's local error beside the jump model"},
      {"jumps.md", fragment, "the steps with a jump and their errors"},
      {"observed_orders.md", fragment, "the observed orders by step halving"},
      {"sensitivity.md", fragment, "how much each configuration amplifies a perturbation"},
      {"reference.md", fragment, "each reference's credential"},
      {"fastest.md", fragment, "the fastest method at each error level"},
      {"fastest_summary.md", fragment, "the fastest methods, in a sentence"},
      {"dropped.md", fragment, "the runs left out of the figures, and why"},
      {"effective_orders.md", fragment, "each method's order fitted on the sweep"},
      {"implicit_variants.md", fragment, "implicit Euler's variants side by side"},
      {"stiff_pick.md", fragment, "the pick for the stiff cloth"},
      {"scaling.md", fragment, "the cost of a step per grid, with fitted exponents"}};
  for (const double h : local_error_steps)
    files.push_back({ch06::local_error_name(h), h == 1e-3 ? figure : data,  // the figure draws h = 1 ms
                     "RK4's local error per step along the (50, 0) trajectory"});
  for (const ch06::Config& c : configs)
    files.push_back({"wp_" + c.name + ".dat", figure, "the work-precision points of " + c.name});
  return files + benchmark_outputs();
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
  cli.declare_outputs([&](const Options&) { return bench_only ? benchmark_outputs() : study_outputs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const SceneParams& scene = opt.scene;
    // The largest cloth held at once: the implicit rows' Newton matrices and factors on the --grid cloth.
    const long long particles = static_cast<long long>(scene.grid.M) * scene.grid.N;
    require_memory(static_cast<double>(particles) * implicit_bytes_per_particle(particles), "--grid",
                   "a run of the implicit methods on a " + std::to_string(scene.grid.M) + "x" +
                       std::to_string(scene.grid.N) + " grid", ": expected a smaller grid");
    prepare_declared_outputs(opt.run.out_dir, bench_only ? benchmark_outputs() : study_outputs(), study_outputs());
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
    ch06::write_near_zero_fragment(dir, ch06::near_zero_springs(scene, hard_horizon, fine, sink));
    std::vector<ch06::LocalError> local_errors;
    for (const double h : local_error_steps)
      local_errors.push_back(ch06::local_error_along_trajectory(scene, hard_horizon, h, sink));
    const ch06::OrderLadder halvings{.horizons = {0.25, hard_horizon}, .k_min = 6, .k_max = quick ? 11 : 15};
    ch06::write_order_loss_fragments(dir, local_errors, ch06::observed_orders(scene, halvings, sink), command);
    ch06::write_sensitivity_fragment(dir, ch06::sensitivity(scene, configs, fine, sink), configs, command);

    // 3. A reference with its credentials, then every method against it on each cloth.
    const ch06::SweepPlan plan{.k_reference = quick ? 12 : 15, .samples = 16, .k_min = 4, .k_max = quick ? 10 : 16,
                               .tolerance_min = 2, .tolerance_max = 10, .max_seconds = quick ? 0.1 : 4.0, .runs = 5};
    std::vector<ch06::ReferenceCheck> references;
    std::vector<ch06::WorkPoint> work;
    for (const ch06::Config& c : configs) {
      ch06::ReferenceCheck& check = references.emplace_back();
      const ch06::Trajectory ref = ch06::reference(scene, c, plan, sink, check);
      const auto points = ch06::work_precision(scene, c, ref, check.agreement, plan, sink);
      work.insert(work.end(), points.begin(), points.end());
    }
    ch06::write_sweep_fragments(dir, references, work, configs, command);

    // 4. The cost of a step against the grid size.
    const ch06::ScalingPlan growth{.sizes = quick ? std::vector<int>{20, 40} : std::vector<int>{20, 40, 80, 160, 320},
                                   .runs = quick ? 3 : 5, .max_step_seconds = quick ? 1.0 : 2.0};
    ch06::write_scaling_fragment(dir, ch06::scaling(scene, growth, sink), command);
    table.commit();
    return 0;
  });
}
