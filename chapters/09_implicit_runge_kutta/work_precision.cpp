// The accuracy studies' machinery: the reference solution (RK4 at a small step, sharing no code with the implicit
// methods) and the runs of each method and Newton variant at a ladder of fixed steps, timed, with their work.
#include "rk4_reference.hpp"
#include "studies.hpp"

#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace cloth;

namespace ch09 {

SceneParams report_cloth(const SceneParams& base) {
  SceneParams report = base;
  report.stiffness = 200;
  report.damping = 20;
  return report;
}

std::vector<double> study_steps(bool quick) {
  return quick ? std::vector<double>{0.02, 0.01, 0.005}
               : std::vector<double>{0.04, 0.02, 0.01, 0.005, 0.0025, 0.00125};
}

// RK4 is explicit and shares no code with the implicit methods; at h_ref its error is far below theirs.
Vector reference_positions(const SceneParams& p, double T, double h_ref) {
  const Scene scene(p);
  ForceField field(scene);
  return rk4_positions(field, T, h_ref);
}

// [work_precision]
// Each method at each step on the scene to T: the largest position error at T against the reference, the processor
// time (best of `repeats`), and the work; one line per run in `path`, one gnuplot index per method and variant.
std::vector<StudyRun> work_precision(const WorkPrecision& spec, const std::string& path) {
  OutputFile out(path);
  std::fprintf(out.get(), "# K = %g, D = %g, T = %g s; error = max |x - x_ref| over the free particles [m]\n"
               "# method newton h error processor_seconds newton_iterations factorizations rhs_evaluations\n",
               spec.scene.stiffness, spec.scene.damping, spec.T);
  const Scene scene(spec.scene);
  ForceField field(scene);
  std::vector<StudyRun> runs;
  for (const NewtonVariant variant : spec.variants) {
    NewtonSettings s = spec.newton;
    s.variant = variant;
    for (const MethodChoice& m : study_methods(s)) {
      if (!spec.only.empty() && std::find(spec.only.begin(), spec.only.end(), m.argument) == spec.only.end())
        continue;
      for (const double h : spec.steps) {
        RunSettings run;
        run.dt = h;
        run.t_end = spec.T;
        run.stop = &interrupt_flag();
        double best = INFINITY;
        RunResult r;
        for (int k = 0; k < spec.repeats; ++k) {
          const std::unique_ptr<NewtonStepper> stepper = make_method(m, field);
          const double start = thread_cpu_seconds();  // the machine's other work does not count
          r = simulate(*stepper, run, false);
          // Stopped by a signal: the study's files are not written, so none lists the run as finished.
          throw_if_interrupted();
          best = std::min(best, thread_cpu_seconds() - start);
        }
        const double error = r.status == RunStatus::ok ? (r.x - spec.reference).lpNorm<Eigen::Infinity>() : NAN;
        runs.push_back({m.row->title, variant, h, error, best, r.counters.factorizations});
        std::fprintf(out.get(), "%s %s %.6g %.6e %.6f %lld %lld %lld\n", m.argument.c_str(),
                     newton_variant_name(variant), h, error, best, r.counters.newton_iterations,
                     r.counters.factorizations, r.counters.rhs_evaluations);
        std::fflush(out.get());
      }
      std::fprintf(out.get(), "\n\n");  // one gnuplot index per method and variant
    }
  }
  out.commit();
  return runs;
}
// [work_precision]

}  // namespace ch09
