// Chapter 10: inextensible cloth by projection. The curtain (20 x 20, K = 1e5 N/m, hung by one edge, released flat)
// stepped by RATTLE and fast projection with the stiff springs held as constraints, against the spring model's
// motion (Dormand-Prince at a tight tolerance), beside the programs a reader would write without the book: a plain
// symplectic Euler loop and Boost.Odeint's RK4 on a plain force loop (plain_fabric.hpp). Each runs a ladder of
// steps; the largest step reaching 1 cm and 1 mm at T is timed (thread CPU time, 5 runs) in the same run.
// The book's own symplectic Euler and RK4 run beside them. Writes projection_runs.md (every run),
// projection_ratio.md (the comparison) and projection_model.md (the spring model's stretch and the inextensible
// model's distance from it) to --out.
#include "../06_speed_vs_error/plain_fabric.hpp"
#include "projection_runs.hpp"
#include "study.hpp"

#include "analysis/reference_trajectory.hpp"
#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "integrators/fast_projection.hpp"
#include "integrators/method_registry.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/timing.hpp"

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

using namespace cloth;
using namespace ch10;

namespace {

SceneParams curtain() {
  SceneParams p = ch10::fabric(20, 1e5);
  p.pins = PinSet::edge;
  return p;
}

// [book_run]
Vector book_run(const Scene& scene, const std::string& method, long long n) {
  ForceField field(scene);
  const auto stepper = make_stepper(method, field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  const double h = T / static_cast<double>(n);
  Vector all(3 * scene.particle_count());
  // As in the peers' loops, nothing is checked between steps: a diverged run ends non-finite (NaN and infinity
  // persist), and its caller reads that from the state at T.
  for (long long k = 0; k < n; ++k)
    if (!stepper->step(h, x, v)) return Vector::Constant(all.size(), NAN);
  scene.all_positions(x, all);
  return all;
}
// [book_run]

Vector plain_symplectic_euler(const ch06::PlainFabric& c, long long n) {
  std::vector<double> y = c.initial_state(), a(static_cast<std::size_t>(3 * c.particles()));
  const double h = T / static_cast<double>(n);
  for (long long k = 0; k < n; ++k) c.symplectic_euler_step(h, y, a);
  return Eigen::Map<const Vector>(y.data(), 3 * c.particles());
}

Vector odeint_rk4(const ch06::PlainFabric& c, long long n) {
  std::vector<double> y = c.initial_state();
  boost::numeric::odeint::runge_kutta4<std::vector<double>> rk4;
  const double h = T / static_cast<double>(n);
  for (long long k = 0; k < n; ++k) rk4.do_step(std::cref(c), y, static_cast<double>(k) * h, h);
  return Eigen::Map<const Vector>(y.data(), 3 * c.particles());
}

// n = T / h for a geometric ladder of steps from h0 down by `ratio`, `count` of them.
std::vector<long long> ladder(double h0, double ratio, int count) {
  std::vector<long long> n;
  for (int k = 0; k < count; ++k) n.push_back(std::llround(std::ceil(T / (h0 * std::pow(ratio, k)))));
  return n;
}

// The spring model's motion at T (Dormand-Prince at a tight tolerance): every particle's position, grid order.
Vector spring_model_at_T(const Scene& scene, ForceField& field, bool quick, double& motion) {
  const double tolerance = quick ? 1e-10 : 1e-11;
  const ReferenceTrajectory reference = reference_trajectory(
      field, scene.initial_positions(), scene.initial_velocities(), T, 1, tolerance, &interrupt_flag());
  throw_if_interrupted();
  Vector rest(3 * scene.particle_count());
  scene.all_positions(scene.initial_positions(), rest);
  motion = largest_distance(reference.frames.back().positions, rest);
  std::printf("reference: dopri5 at %g, %lld steps; motion at T %.3f m\n", tolerance, reference.steps, motion);
  return reference.frames.back().positions;
}

// The spring model's stretch: the structural springs' largest |l - L0| in the reference motion at T, against the
// inextensible model's distance from the spring model at RATTLE's finest step (projection_model.md).
void model_difference(const Scene& scene, ForceField& field, const Vector& truth, double motion, long long finest,
                      double rattle_error, const std::string& dir, const std::string& command) {
  ConstrainedCloth probe(field, "rattle", ConstrainedScheme::rattle);
  Vector free_truth(scene.dof_count());
  for (int s = 0; s < scene.free_count(); ++s)
    free_truth.segment<3>(3 * s) = truth.segment<3>(3 * scene.particle_of_slot(s));
  const double stretch = probe.largest_violation(free_truth);
  write_text_fragment(
      dir + "/projection_model.md",
      format("On the curtain at T = %g s (the farthest particle %.3g m from its rest position) the spring model "
             "stretches its structural springs by up to %.2g m, and RATTLE at h = %.3g s ends %.2g m from the "
             "spring model's positions (%d structural springs held, %d shear springs compliant, %d flexion "
             "springs and the dampers as forces).\n",
             T, motion, stretch, T / static_cast<double>(finest), rattle_error, probe.hard_constraint_count(),
             probe.constraint_count() - probe.hard_constraint_count(), scene.springs().count(SpringFamily::flexion)) +
          measured_by_line(command));
}

const OutputList projection_outputs = {
    {"projection_runs.md", OutputKind::fragment, "every run of every program's ladder of steps: its error at T"},
    {"projection_ratio.md", OutputKind::fragment, "each program's coarsest step to 1 cm and 1 mm, timed"},
    {"projection_model.md", OutputKind::fragment, "the spring model's stretch and RATTLE's distance from it"}};

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch10_projection",
                  "Chapter 10: the curtain as inextensible cloth (RATTLE and fast projection on constrained springs)\n"
                  "against the spring model, timed beside a plain symplectic Euler loop and Boost.Odeint's RK4 at\n"
                  "the largest steps reaching 1 cm and 1 mm at T = 0.5 s.");
  cli.use_common({"--out"});
  bool quick = false;
  cli.add_switch("--quick", "shorter step ladders and a looser reference (the book's build runs this)",
                 [&] { quick = true; });
  cli.declare_outputs([](const Options&) { return projection_outputs; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const std::string& dir = opt.run.out_dir;
    prepare_declared_outputs(dir, projection_outputs);
    const std::string command = reader_command(argc, argv);
    const SceneParams p = curtain();
    const Scene scene(p);
    ForceField field(scene);
    double motion = 0;
    const Vector truth = spring_model_at_T(scene, field, quick, motion);

    // [contenders]
    const ch06::PlainFabric plain(p.grid.M, p.grid.N, p.grid.d, p.stiffness, p.damping, p.mass, p.gravity,
                                  p.initial_velocity_z, /*edge=*/true);
    const double h_se = 4.4e-5, h_rk4 = 6.4e-5;  // just inside each explicit method's stable step here
    std::vector<Contender> contenders = {
        {"RATTLE", true, ladder(T / 600, 0.5, quick ? 2 : 4),
         [&](long long n) { return book_run(scene, "rattle", n); }},
        {"fast projection", true, ladder(T / 600, 0.5, quick ? 2 : 4),
         [&](long long n) { return book_run(scene, "fast_projection", n); }},
        {"symplectic Euler (the book's forces)", true, ladder(h_se, 0.5, quick ? 1 : 3),
         [&](long long n) { return book_run(scene, "symplectic_euler", n); }},
        {"RK4 (the book's forces)", true, ladder(h_rk4, 0.5, quick ? 1 : 2),
         [&](long long n) { return book_run(scene, "rk4", n); }},
        {"plain symplectic Euler loop", false, ladder(h_se, 0.5, quick ? 1 : 3),
         [&](long long n) { return plain_symplectic_euler(plain, n); }},
        {"Boost.Odeint RK4, plain loop", false, ladder(h_rk4, 0.5, quick ? 1 : 2),
         [&](long long n) { return odeint_rk4(plain, n); }},
    };
    // [contenders]

    Ladders measured = run_ladders(contenders, truth, dir, command);  // projection_runs.md
    time_at_levels(contenders, measured, dir, command);                // projection_ratio.md
    const long long finest = contenders[0].steps.back();              // RATTLE's finest step
    model_difference(scene, field, truth, motion, finest, measured[0][finest].error, dir, command);
    return 0;
  });
}
