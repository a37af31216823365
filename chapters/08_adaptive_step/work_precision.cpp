// Chapter 8's benchmark: error at T against in-process time for the project's adaptive pairs and for Boost.Odeint's
// controlled runge_kutta_dopri5 and runge_kutta_cash_karp54, each odeint stepper built twice: as the
// straightforward program a reader would write (plain_cloth.hpp) and driving the project's own forces. Errors are
// measured against a long-double reference computed here and checked against a second one (comparison.hpp).
#include "comparison.hpp"

#include "base/format_number.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"
#include "program/output_kinds.hpp"
#include "program/output_spec.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// The files the program writes into --out, declared once (program/output_spec.hpp).
OutputList outputs() {
  using namespace cloth::output_kinds;
  return {{"work_precision.dat", figure, "every run of both sides: tolerance, error, time, work"},
          {"levels.dat", data, "each side's fastest run at each error level"},
          {"levels.md", fragment, "each side's fastest run at each error level, and the ratio"},
          {"reference.md", fragment, "the reference and its credential"},
          {"spring_turn.md", fragment, "dopri5 with and without the spring-turn check"},
          {"evaluation_cost.md", fragment, "what one right-hand side costs on each side"},
          {"tries.md", fragment, "how many configurations each side tried"}};
}

// The tolerance ladder's decades: rtol = atol from 10^-loosest to 10^-tightest.
struct Decades {
  int loosest = 2, tightest = 11;
};

// rtol = atol = 10^-k and 3 10^-(k+1): the same tolerances for every configuration of both sides, loosest first.
std::vector<double> tolerance_ladder(const Decades& decades) {
  std::vector<double> tolerances;
  for (int k = decades.loosest; k <= decades.tightest; ++k)
    tolerances.insert(tolerances.end(), {std::pow(10.0, -k), 3 * std::pow(10.0, -k - 1)});
  tolerances.pop_back();  // the ladder ends on 10^-tightest
  return tolerances;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int runs = 5;
  CommandLine cli("ch08_work_precision",
                  "Chapter 8: work-precision of the adaptive pairs against Boost.Odeint on the report's cloth.\n"
                  "--t-end is the horizon; --K, --damping and the other scene flags apply.");
  // The scene flags and the horizon; no --dt or --frames: every run chooses its own steps and records no frames.
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--K-flexion", "--damping", "--damping-model", "--springs",
                  "--pins", "--v0", "--t-end", "--out"});
  cli.set_default("--t-end", "1");  // the whole fall through the first folds, as Chapter 8's diagrams show it
  cli.add_switch("--quick", "a reduced sweep for the plots target (well under a minute)", [&] { quick = true; });
  cli.add_value("--runs", "N", "timed runs per point, the best is kept (default 5)",
                [&](const std::string& s) { runs = static_cast<int>(parse_count(s, 1, 100)); });
  cli.declare_outputs([](const Options&) { return outputs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    prepare_declared_outputs(opt.run.out_dir, outputs());
    const std::string command = reader_command(argc, argv);
    const Scene scene(opt.scene);
    const Decades decades = quick ? Decades{.loosest = 3, .tightest = 8} : Decades{.loosest = 2, .tightest = 11};
    const ch08::ComparisonPlan plan{opt.run, tolerance_ladder(decades), runs};

    // 1. The reference and its credential.
    const double start = wall_seconds();
    const ch08::Reference ref = ch08::long_double_reference(scene, plan.run.t_end, quick ? 1e-10 : 1e-14);
    std::printf("reference: long double, odeint dopri5 and cash_karp54 at tol %g (%lld and %lld steps, %.1f s): "
                "they agree to %.2e m at T = %g s\n", ref.tolerance, ref.steps, ref.check_steps,
                wall_seconds() - start, ref.agreement, plan.run.t_end);
    ch08::write_reference(opt.run.out_dir + "/", ref, plan.run.t_end, command);

    // 2. Both sides at the same tolerances, each run timed whole.
    std::vector<ch08::Row> rows = ch08::project_runs(scene, ref.y, plan);
    const std::vector<ch08::Row> theirs = ch08::odeint_runs(scene, ref.y, plan);
    rows.insert(rows.end(), theirs.begin(), theirs.end());

    // 3. What the page quotes.
    ch08::write_comparison(opt.run.out_dir + "/", rows, ref, plan, opt.scene, command);
    return 0;
  });
}
