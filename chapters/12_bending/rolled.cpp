// Chapter 12's check of bending in XPBD and local/global (rolled.md): a small sheet rolled onto a cylinder about
// its pinned edge and released, run by each method and by implicit Euler at the same step; the gap between them
// and the energy each keeps.
#include "report.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

using namespace cloth;

namespace {

// The sheet of the book's test: 5 x 4 particles 5 cm apart, springs of 100 N/m, D = 0.01, the hinge energy with
// B = 1e-3 N m, no gravity, its edge j = N-1 pinned.
SceneParams rolled_sheet() {
  SceneParams p;
  p.grid = Grid{5, 4, 0.05};
  p.mass = 6.25e-4;
  p.stiffness = 100;
  p.damping = 0.01;
  p.pins = PinSet::edge;
  p.bending = BendingModel::hinge;
  p.bending_rigidity = 1e-3;
  p.gravity = 0;
  p.initial_velocity_z = 0;
  return p;
}

// The free particles laid onto a cylinder of radius R about the pinned edge, each at its arc length from the edge:
// an isometry but for the chords, so the bending energy drives the motion.
Vector rolled_positions(const Scene& scene, double R) {
  Vector x = scene.initial_positions();
  const double edge_y = (scene.grid().N - 1) * scene.grid().d;
  for (int slot = 0; slot < scene.free_count(); ++slot) {
    const double s = edge_y - (scene.particle_of_slot(slot) % scene.grid().N) * scene.grid().d;
    x[3 * slot + 1] = edge_y - R * std::sin(s / R);
    x[3 * slot + 2] = R * (1 - std::cos(s / R));
  }
  return x;
}

}  // namespace

// [rolled_study]
// Each method's iterations converged (200 sweeps or local/global iterations, Newton to 1e-12), so that what
// differs from implicit Euler is the bending force taken at the step's start, not an unfinished iteration.
void write_rolled(const std::string& dir, const std::string& command) {
  const Scene scene(rolled_sheet());
  ForceField field(scene);
  const Vector x0 = rolled_positions(scene, 0.15), v0 = Vector::Zero(scene.dof_count());
  const double E0 = field.energy(x0, v0).total(), T = 0.1;
  MethodSettings converged;
  converged.local_global_iterations = 200;
  converged.xpbd_iterations = 200;
  converged.newton.tolerance = 1e-12;
  const auto run = [&](const char* name, double h, Vector& x) {
    throw_if_interrupted();
    auto stepper = make_stepper(name, field, converged);
    x = x0;
    Vector v = v0;
    for (long k = 0; k < std::lround(T / h); ++k)
      if (!stepper->step(h, x, v)) throw std::runtime_error(std::string(name) + ": a step failed on the rolled sheet");
    return field.energy(x, v).total() / E0;
  };
  MarkdownTable table({"method", "h [ms]", "implicit Euler's largest motion [cm]",
                       "gap to implicit Euler [% of that motion]", "E(T) / E(0)", "implicit Euler's E(T) / E(0)"},
                      "lrrrrr");
  for (const char* name : {"local_global", "xpbd"})
    for (const double h : {4e-4, 2e-4}) {
      Vector reference, x;
      const double E_reference = run("implicit_euler", h, reference), E = run(name, h, x);
      const double motion = (reference - x0).lpNorm<Eigen::Infinity>();
      table.add_row({name, format_number(1e3 * h), format_fixed(100 * motion, 2), format_fixed(100 * (x - reference).lpNorm<Eigen::Infinity>() / motion, 3),
                     format_fixed(E, 3), format_fixed(E_reference, 3)});
    }
  write_table_fragment(dir + "/rolled.md", table, command);
}
// [rolled_study]
