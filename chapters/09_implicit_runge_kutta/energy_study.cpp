// The energy study: every implicit method on the undamped cloth, whose energy any change of is the method's
// (numerical damping against symplecticity).
#include "studies.hpp"

#include "base/format_number.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cstdio>

using namespace cloth;

namespace ch09 {

// [energy_study]
// Every method on the undamped cloth (D = 0) at the run's h to its T: energy.dat per method in its own folder,
// and energy_summary.dat with E(T) / E(0) and the work. Returns 0, or 128 + signal when a run was interrupted: the
// interrupted run's own run.txt says so, and the summary, which would list it as finished, is not written.
int energy_study(const Study& study) {
  const Options& opt = study.opt;
  SceneParams p = opt.scene;
  p.damping = 0;
  OutputFile summary(study.dir + "/energy_summary.dat");
  std::fprintf(summary.get(), "# undamped cloth, K = %g, h = %g s, T = %g s\n# method E(T)/E(0) min_E/E(0) "
               "max_E/E(0) newton_iterations factorizations wall_seconds\n", p.stiffness, opt.run.dt, opt.run.t_end);
  NewtonSettings kept = study.newton;
  kept.variant = NewtonVariant::modified;  // converged to the same tolerance as full Newton, at a fraction of the cost
  const std::string scene = std::string("undamped cloth, h = ") + format_number(opt.run.dt) + " s, T = " +
                            format_number(opt.run.t_end) + " s";
  MarkdownTable table({scene, "E(T) / E(0)", "smallest E / E(0)", "largest E / E(0)"}, "lrrr");
  for (const MethodChoice& m : study_methods(kept)) {
    RunSettings run = opt.run;
    run.out_dir = study.dir + "/energy_" + m.argument;
    RunResult r;
    if (const int status = run_cloth(p, run, m, study.program, &r); status >= 128) return status;
    const double E0 = r.energy.front().energy.total();
    double lo = E0, hi = E0;
    for (const EnergySample& e : r.energy) lo = std::min(lo, e.energy.total()), hi = std::max(hi, e.energy.total());
    std::fprintf(summary.get(), "%s %.6f %.6f %.6f %lld %lld %.4f\n", m.argument.c_str(),
                 r.energy.back().energy.total() / E0, lo / E0, hi / E0, r.counters.newton_iterations,
                 r.counters.factorizations, r.wall_seconds);
    table.add_row({m.row->title, format_fixed(r.energy.back().energy.total() / E0, 5), format_fixed(lo / E0, 5),
                   format_fixed(hi / E0, 5)});
  }
  summary.commit();
  write_table_fragment(study.dir + "/energy_summary.md", table, study.command);
  return 0;
}
// [energy_study]

}  // namespace ch09
