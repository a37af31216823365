// Chapter 10: inextensible cloth by projection. The curtain (20 x 20, K = 1e5 N/m, hung by one edge, released flat)
// stepped by RATTLE and fast projection with the stiff springs held as constraints, against the spring model's
// motion (Dormand-Prince at a tight tolerance), beside the programs a reader would write without the book: a plain
// symplectic Euler loop and Boost.Odeint's RK4 on a plain force loop (plain_fabric.hpp). Each runs a ladder of
// steps; the largest step reaching 1 cm and 1 mm at T is timed (thread CPU time, 5 runs) in the same run.
// The book's own symplectic Euler and RK4 run beside them. Writes projection_runs.md (every run),
// projection_ratio.md (the comparison) and projection_model.md (the spring model's stretch and the inextensible
// model's distance from it) to --out.
#include "plain_fabric.hpp"
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
using ch10::format;

namespace {

constexpr double T = 0.5;                      // the curtain has swung down past the vertical [s]
constexpr double levels[] = {1e-2, 1e-3};      // the accuracies asked for [m]

SceneParams curtain() {
  SceneParams p = ch10::fabric(20, 1e5);
  p.pins = PinSet::edge;
  return p;
}

// A program of the comparison: its name on the page, whether it is the book's, the steps it tries (as step counts
// over T, coarse to fine), and a run of n steps returning every particle's position at T in grid order (NaN when
// the run failed).
struct Contender {
  std::string title;
  bool book;
  std::vector<long long> steps;
  std::function<Vector(long long)> run;
};

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

Vector plain_symplectic_euler(const ch10::PlainFabric& c, long long n) {
  std::vector<double> y = c.initial_state(), a(static_cast<std::size_t>(3 * c.particles()));
  const double h = T / static_cast<double>(n);
  for (long long k = 0; k < n; ++k) c.symplectic_euler_step(h, y, a);
  return Eigen::Map<const Vector>(y.data(), 3 * c.particles());
}

Vector odeint_rk4(const ch10::PlainFabric& c, long long n) {
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

struct Measured {
  double error = NAN;
  Timing timing;
  bool timed = false;
};

std::string seconds_text(const Timing& t) {
  return format("%.3g (%.3g-%.3g)", t.median_cpu, t.fastest_cpu, t.slowest_cpu);
}

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
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const std::string dir = opt.run.out_dir;
    prepare_outputs(dir, {"projection_runs.md", "projection_ratio.md", "projection_model.md"});
    const std::string command = reader_command(argc, argv);
    const SceneParams p = curtain();
    const Scene scene(p);
    ForceField field(scene);

    // The spring model's motion at T.
    const double tolerance = quick ? 1e-10 : 1e-11;
    const ReferenceTrajectory reference = reference_trajectory(
        field, scene.initial_positions(), scene.initial_velocities(), T, 1, tolerance, &interrupt_flag());
    throw_if_interrupted();
    const Vector& truth = reference.frames.back().positions;
    Vector rest(3 * scene.particle_count());
    scene.all_positions(scene.initial_positions(), rest);
    const double motion = largest_distance(truth, rest);
    std::printf("reference: dopri5 at %g, %lld steps; motion at T %.3f m\n", tolerance, reference.steps, motion);

    // [contenders]
    const ch10::PlainFabric plain(p.grid.M, p.grid.N, p.grid.d, p.stiffness, p.damping, p.mass, p.gravity,
                                  p.initial_velocity_z, /*edge=*/true);
    const double h_se = 4.4e-5, h_rk4 = 6.4e-5;  // just inside each explicit method's stable step here
    std::vector<Contender> contenders = {
        {"RATTLE", true, ladder(T / 600, 0.5, quick ? 2 : 4), [&](long long n) { return book_run(scene, "rattle", n); }},
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

    std::vector<std::map<long long, Measured>> measured(contenders.size());
    MarkdownTable runs({"program", "step h [s]", "steps", "largest error at T [m]"}, "lrrr");
    for (std::size_t c = 0; c < contenders.size(); ++c) {
      for (const long long n : contenders[c].steps) {
        Measured& m = measured[c][n];
        const Vector at_T = contenders[c].run(n);
        m.error = at_T.allFinite() ? largest_distance(at_T, truth) : NAN;  // NaN: the run failed
        throw_if_interrupted();
        std::printf("%-30s h = %.3g: error %.3g m\n", contenders[c].title.c_str(), T / static_cast<double>(n), m.error);
        runs.add_row({contenders[c].title, format_number(T / static_cast<double>(n), 3), std::to_string(n),
                      std::isfinite(m.error) ? format_number(m.error, 3) : "failed"});
        if (m.error <= levels[1]) break;  // finer steps would only cost more
      }
    }

    // For each level, each contender's coarsest step reaching it, timed.
    std::string ratios;
    MarkdownTable fastest({"level", "program", "step h [s]", "largest error at T [m]",
                           "CPU s, median of 5 (fastest-slowest)"},
                          "rlrrr");
    const TimingPlan plan{5, 1, 1};
    for (const double level : levels) {
      int best_book = -1, best_peer = -1;
      std::vector<long long> chosen(contenders.size(), 0);
      for (std::size_t c = 0; c < contenders.size(); ++c) {
        for (const long long n : contenders[c].steps) {
          const auto it = measured[c].find(n);
          if (it != measured[c].end() && it->second.error <= level) {
            chosen[c] = n;
            break;
          }
        }
        if (chosen[c] == 0) {
          fastest.add_row({format_number(level), contenders[c].title, "", "not reached", ""});
          continue;
        }
        Measured& m = measured[c][chosen[c]];
        if (!m.timed) {
          m.timing = time_runs([&] { (void)contenders[c].run(chosen[c]); }, plan);
          m.timed = true;
          throw_if_interrupted();
        }
        fastest.add_row({format_number(level), contenders[c].title,
                         format_number(T / static_cast<double>(chosen[c]), 3), format_number(m.error, 3),
                         seconds_text(m.timing)});
        int& best = contenders[c].book ? best_book : best_peer;
        if (best < 0 || m.timing.median_cpu < measured[static_cast<std::size_t>(best)][chosen[static_cast<std::size_t>(best)]].timing.median_cpu)
          best = static_cast<int>(c);
      }
      if (best_book < 0 || best_peer < 0) {
        ratios += format("- %s: %s.\n", format_number(level).c_str(),
                         best_book < 0 ? "no method of the book reaches it" : "no peer reaches it");
        continue;
      }
      const auto& b = measured[static_cast<std::size_t>(best_book)][chosen[static_cast<std::size_t>(best_book)]].timing;
      const auto& q = measured[static_cast<std::size_t>(best_peer)][chosen[static_cast<std::size_t>(best_peer)]].timing;
      ratios += format("- %s m: %s %.3g s against %s %.3g s: **%.2f x** (from %.2f to %.2f over the spread of "
                       "both).\n",
                       format_number(level).c_str(), contenders[static_cast<std::size_t>(best_book)].title.c_str(),
                       b.median_cpu, contenders[static_cast<std::size_t>(best_peer)].title.c_str(), q.median_cpu,
                       b.median_cpu / q.median_cpu, b.fastest_cpu / q.slowest_cpu, b.slowest_cpu / q.fastest_cpu);
    }
    std::printf("%s", ratios.c_str());
    write_table_fragment(dir + "/projection_runs.md", runs, command);
    write_text_fragment(dir + "/projection_ratio.md",
                        fastest.markdown() + "\nThe book's fastest against the fastest peer (ratio of the medians):\n\n" +
                            ratios + "\n" + measured_by_line(command));

    // The spring model's stretch: the structural springs' largest |l - L0| in the reference motion at T, against the
    // inextensible model's distance from the spring model at RATTLE's finest step.
    ConstrainedCloth probe(field, "rattle", ConstrainedScheme::rattle);
    Vector free_truth(scene.dof_count());
    for (int s = 0; s < scene.free_count(); ++s)
      free_truth.segment<3>(3 * s) = truth.segment<3>(3 * scene.particle_of_slot(s));
    const double stretch = probe.largest_violation(free_truth);
    const long long finest = contenders[0].steps.back();
    write_text_fragment(
        dir + "/projection_model.md",
        format("On the curtain at T = %g s (the farthest particle %.3g m from its rest position) the spring model "
               "stretches its structural springs by up to %.2g m, and RATTLE at h = %.3g s ends %.2g m from the "
               "spring model's positions (%d structural springs held, %d shear springs compliant, %d flexion "
               "springs and the dampers as forces).\n",
               T, motion, stretch, T / static_cast<double>(finest), measured[0][finest].error,
               probe.hard_constraint_count(), probe.constraint_count() - probe.hard_constraint_count(),
               scene.springs().count(SpringFamily::flexion)) +
            measured_by_line(command));
    return 0;
  });
}
