// Implicit Euler on the report scene, solved by ARKODE and by the book: the same equations, the same step, and how
// far each ends from the book's implicit Euler solved tightly.
#include "benchmark.hpp"

#include "base/format_number.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <algorithm>

using namespace cloth;

namespace ch09 {

// On the report scene (200, 20), implicit Euler at h = 0.01 s over T = 1 s: ARKODE given the one-stage table at
// that fixed step, and the book's implicit Euler with full and with modified Newton; the time of each, and how far
// each ends from the book's implicit Euler solved to 1e-12.
void report_scene_comparison(const SceneParams& base, bool quick, const std::string& dir, const std::string& command) {
  SceneParams p = base;
  p.stiffness = 200;
  p.damping = 20;
  const double T = 1, h = 0.01;
  const int repeats = quick ? 1 : 3;
  const Scene scene(p);
  ForceField field(scene);
  Vector tight_x;
  const Vector origin = Vector::Zero(field.dof_count());
  fixed_step_run(field, "implicit_euler", h, 1e-12, NewtonVariant::full, {T, origin, 1}, &tight_x);
  MarkdownTable table({"implicit Euler, h = 0.01 s, (K, D) = (200, 20), T = 1 s", "Newton tolerance", "time [s]",
                       "time / ARKODE's", "largest distance from the tightly solved solution [m]"},
                      "llrrr");
  double arkode_seconds = INFINITY;
  Vector x, v;
  Outcome out;
  const SundialsSettings backward_euler{"arkode-backward-euler", T, 1e-8, 1e-8, h};
  for (int k = 0; k < repeats; ++k) {
    out = sundials_run(backward_euler, field, x, v);
    throw_if_interrupted();
    arkode_seconds = std::min(arkode_seconds, out.seconds);
  }
  table.add_row({"ARKODE, one-stage table, fixed step, KLU", "rtol = atol = 1e-8", format_number(arkode_seconds, 2),
                 "1", out.ok ? format_number((x - tight_x).lpNorm<Eigen::Infinity>(), 2)
                        : std::string(run_status_name(out.end.status)) + ": " + out.end.reason});
  for (const NewtonVariant variant : {NewtonVariant::full, NewtonVariant::modified}) {
    const Timed t = fixed_step_run(field, "implicit_euler", h, 1e-8, variant, {T, tight_x, repeats});
    table.add_row({std::string("the book's implicit_euler, ") + newton_variant_name(variant) + " Newton",
                   "`--newton-tol 1e-8`", format_number(t.seconds, 2), format_number(t.seconds / arkode_seconds, 2),
                   format_number(t.error, 2)});
  }
  write_table_fragment(dir + "/report_scene.md", table, command);
}

}  // namespace ch09
