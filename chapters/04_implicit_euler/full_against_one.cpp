// Baraff and Witkin's one Newton iteration per step against full Newton at the report's three (K, D): iterations,
// factorizations, the energy at the end and how far apart the two cloths end.
#include "report.hpp"

#include "base/format_number.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <cmath>
#include <cstdio>

namespace ch04 {

using namespace cloth;

int full_against_one(const Study& study, const std::function<NewtonSettings(double, double)>& newton_for) {
  const Options& opt = study.opt;
  const std::string& program = study.program;
  const std::string& command = study.command;
  const std::string dir = opt.run.out_dir;
  OutputFile summary_file(dir + "/comparison.dat");
  std::FILE* summary = summary_file.get();
  std::fprintf(summary, "# K D newton_per_step_full newton_per_step_one factorizations_full factorizations_one "
                        "wall_full wall_one E_final_full E_final_one max_position_difference\n");
  MarkdownTable table({"K, D", "Newton iterations per step, full", "factorizations full / one", "E(2 s) full [J]",
                       "E(2 s) one iteration [J]", "energy lost by 2 s, full",
                       "largest position difference at 2 s [m]"},
                      "lrrrrrr");
  for (const ReportCase& c : report_cases) {
    const SceneParams p = with_case(opt.scene, c);
    const NewtonSettings full = newton_for(c.K, c.D);
    const Outcome a = run_cloth(p, opt.run, full, dir + "/" + report_folder("full", c), program);
    if (a.status >= 128) return a.status;  // interrupted: the run said so; comparison.dat is not written
    NewtonSettings one = full;
    one.variant = NewtonVariant::one;
    const Outcome b = run_cloth(p, opt.run, one, dir + "/" + report_folder("one", c), program);
    if (b.status >= 128) return b.status;
    const double diff = a.result.t == b.result.t ? (a.result.x - b.result.x).lpNorm<Eigen::Infinity>() : NAN;
    std::fprintf(summary, "%g %g %.4f %.4f %lld %lld %.4f %.4f %.8g %.8g %.4e\n", c.K, c.D, a.result.newton_iterations_per_step(),
                 b.result.newton_iterations_per_step(), a.result.counters.factorizations, b.result.counters.factorizations,
                 a.result.wall_seconds, b.result.wall_seconds, a.result.energy.back().energy.total(),
                 b.result.energy.back().energy.total(), diff);
    std::printf("K = %g, D = %g: full Newton %.3f iterations/step, one iteration: largest position difference at "
                "t = %g s: %.4g m\n", c.K, c.D, a.result.newton_iterations_per_step(), a.result.t, diff);
    const double E0 = a.result.energy.front().energy.total(), E_full = a.result.energy.back().energy.total();
    table.add_row({format_number(c.K) + ", " + format_number(c.D), format_fixed(a.result.newton_iterations_per_step(), 2),
                   std::to_string(a.result.counters.factorizations) + " / " +
                       std::to_string(b.result.counters.factorizations),
                   format_fixed(E_full, 2), format_fixed(b.result.energy.back().energy.total(), 2),
                   format_number(100 * (E0 - E_full) / E0, 2) + "%", format_number(diff, 2)});
  }
  summary_file.commit();
  write_table_fragment(dir + "/report_runs.md", table, command);
  return 0;
}

}  // namespace ch04
