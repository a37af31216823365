// Chapter 10: real cloth in physical units. The fabric preset and the same square metre at finer grids; the
// explicit methods' stable step, predicted from the lattice and measured; the practitioner's question (what
// each method costs to reach 1 cm and 1 mm at T); and the map of the cheapest method over resolution and
// stiffness, predicted by a cost model and checked by measurement where affordable. --quick is the reduced sweep
// the plots target runs; without it the full sweep runs. --curtain runs the study of cloth that moves instead.
#include "curtain.hpp"
#include "study.hpp"

#include "analysis/fastest_modes.hpp"
#include "analysis/lattice_frequency.hpp"
#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "model/fabric.hpp"
#include "program/command_line.hpp"
#include "program/interrupt.hpp"
#include "program/timing.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

using namespace cloth;
using ch10::format;

namespace {

struct Settings {
  bool quick = false;
  bool curtain_only = false;  ///< only the study of cloth that moves (curtain.cpp)
  std::string out;
  std::string command;  ///< what a reader types to measure the tables again (reader_command)
};

// ---------------------------------------------------------------------------------------------------------------
// The fabric preset, and the same square metre at finer grids.

MarkdownTable preset_table() {
  const FabricMeasurements cotton;
  MarkdownTable t({"particles per side", "spacing d [m]", "particle mass m = ρ_A d² [kg]",
                   "k_s = k_sh [N/m]", "k_f [N/m]", "ω_max [rad/s]", "RK4's stable step [s]"},
                  "rrrrrrr");
  for (int n : {20, 39, 77, 153}) {
    const SceneParams p = fabric_scene(cotton, {0.95, n, 20.0});
    const double w = lattice_fastest_frequency({p.stiffness, p.stiffness, *p.flexion_stiffness, p.mass});
    t.add_row({format("%d", n), format("%.4g", p.grid.d), format("%.4g", p.mass), format("%.6g", p.stiffness),
               format("%.3g", *p.flexion_stiffness), format("%.4g", w), format("%.3g", 2 * std::sqrt(2.0) / w)});
  }
  return t;
}

// [refinement]
// RK4 at 90 % of its stable step (within ~1e-7 m of the exact motion, the practitioner's table shows) on the fabric preset with n particles per side; the positions of every particle at
// t = k T / snapshots, k = 0..snapshots.
std::vector<Vector> fabric_motion(int n, double T, int snapshots, long long& steps, double& seconds) {
  const SceneParams p = fabric_scene(FabricMeasurements{}, {0.95, n, 20.0});
  const Scene scene(p);
  ForceField field(scene);
  auto rk4 = ch10::make_method("rk4", field);
  const double omega = lattice_fastest_frequency({p.stiffness, p.stiffness, *p.flexion_stiffness, p.mass});
  steps = snapshots * static_cast<long long>(std::ceil(T / snapshots / (0.9 * 2 * std::sqrt(2.0) / omega)));
  const double h = T / static_cast<double>(steps);
  Vector x = scene.initial_positions(), v = scene.initial_velocities(), all(3 * scene.particle_count());
  std::vector<Vector> out;
  const double t0 = thread_cpu_seconds();
  for (long long k = 0; k <= steps; ++k) {
    if (k % (steps / snapshots) == 0) {
      scene.all_positions(x, all);
      out.push_back(all);
    }
    if (k < steps) rk4->step(h, x, v);
  }
  seconds = thread_cpu_seconds() - t0;
  return out;
}
// [refinement]

// The same square metre with 20, 39, 77 (and 153) particles per side: particle (i, j) of one grid sits where
// particle (2i, 2j) of the next sits, so their positions at T are compared directly.
void refinement(const Settings& s) {
  const std::vector<int> sizes = s.quick ? std::vector<int>{20, 39} : std::vector<int>{20, 39, 77, 153};
  const double T = 0.5;
  const int snapshots = 5;
  std::vector<std::vector<Vector>> motion;
  std::vector<long long> steps(sizes.size());
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    double seconds = 0;
    motion.push_back(fabric_motion(sizes[k], T, snapshots, steps[k], seconds));
    std::printf("refinement: %d x %d, %lld RK4 steps, %.2f s\n", sizes[k], sizes[k], steps[k], seconds);
  }
  MarkdownTable table({"particles per side", "RK4 step [s]", "steps",
                       "largest distance to the next finer grid at t = 0.1 s, 0.2 s, ..., 0.5 s [m]"}, "rrrl");
  std::string dat = "# n h steps then the largest distance to the next finer grid at t = 0.1 ... 0.5\n";
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    std::string distances;
    dat += format("%d %.6g %lld", sizes[k], T / static_cast<double>(steps[k]), steps[k]);
    if (k + 1 < sizes.size()) {
      for (int f = 1; f <= snapshots; ++f) {
        // [refinement_compare]
        // motion[k][f]: every particle's position at snapshot f (t = f T / 5) on the grid with sizes[k] particles
        // per side (fabric_motion above), particle (i, j) at entry i n + j. Its partner on the next finer grid,
        // with sizes[k + 1] per side, is particle (2i, 2j).
        double distance = 0;
        const int n = sizes[k], fine = sizes[k + 1];
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j)
            distance = std::max(distance, (motion[k][f].segment<3>(3 * (i * n + j)) -
                                           motion[k + 1][f].segment<3>(3 * (2 * i * fine + 2 * j)))
                                              .norm());
        // [refinement_compare]
        distances += format("%s%.2g", f == 1 ? "" : ", ", distance);
        dat += format(" %.6e", distance);
      }
    }
    dat += "\n";
    table.add_row({format("%d", sizes[k]), format("%.3g", T / static_cast<double>(steps[k])),
                   format("%lld", steps[k]), k + 1 < sizes.size() ? distances : "(finest)"});
  }
  write_table_fragment(s.out + "/refinement.md", table, s.command);
  ch10::write_text(s.out, "refinement.dat", dat);
  // The 39 x 39 fabric at the snapshot times, for the figure: one gnuplot index block per time.
  std::string frames = "# i j x y z of the 39 x 39 fabric, one block per t = 0, 0.1, ..., 0.5 s\n";
  const int n = sizes[1];
  for (const Vector& all : motion[1]) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j)
        frames += format("%d %d %.6g %.6g %.6g\n", i, j, all[3 * (i * n + j)], all[3 * (i * n + j) + 1],
                         all[3 * (i * n + j) + 2]);
      frames += "\n";
    }
    frames += "\n";
  }
  ch10::write_text(s.out, "fabric_frames.dat", frames);
}

// ---------------------------------------------------------------------------------------------------------------
// The explicit stable step: predicted from the lattice, from the finite cloth's spectrum, and measured.

// [stable_step]
// Bisection (in log h) between half and twice the predicted step: `halvings` bisections leave the answer within
// a factor 4^(1/2^halvings), 2 % after 6.
double measured_stable_step(const Scene& scene, const std::string& method, double predicted, int halvings, int steps) {
  double stable = 0.5 * predicted, unstable = 2 * predicted;
  if (!ch10::stays_bounded(scene, method, stable, steps) || ch10::stays_bounded(scene, method, unstable, steps)) return NAN;
  for (int k = 0; k < halvings; ++k) {
    const double mid = std::sqrt(stable * unstable);
    (ch10::stays_bounded(scene, method, mid, steps) ? stable : unstable) = mid;
  }
  return stable;
}
// [stable_step]

// Stability interval on the imaginary axis: symplectic Euler 2, RK4 2 sqrt 2.
double stability_reach(const std::string& method) { return method == "rk4" ? 2 * std::sqrt(2.0) : 2.0; }

void stable_steps(const Settings& s, const std::vector<double>& stiffnesses) {
  MarkdownTable table({"grid", "K [N/m]", "ω_max, lattice [rad/s]", "ω_max, this cloth [rad/s]",
                       "symplectic Euler: predicted / measured h [s]", "RK4: predicted / measured h [s]"},
                      "lrrrrr");
  double worst[2] = {0, 0};  // the largest relative difference of prediction and measurement, per method
  std::string dat = "# n K omega_lattice omega_cloth se_predicted se_measured rk4_predicted rk4_measured\n";
  for (int n : s.quick ? std::vector<int>{20} : std::vector<int>{20, 39}) {
    for (double K : stiffnesses) {
      if (s.quick && K != 1e5) continue;
      const SceneParams p = ch10::fabric(n, K);
      const Scene scene(p);
      ForceField field(scene);
      const double lattice = lattice_fastest_frequency({K, K, K, p.mass});
      const double cloth_omega = fastest_rest_frequency(field);
      const double se = 2 / lattice, rk = 2 * std::sqrt(2.0) / lattice;
      const int halvings = s.quick ? 6 : 9, steps = s.quick ? 1000 : 2000;
      const double se_m = measured_stable_step(scene, "symplectic_euler", se, halvings, steps);
      const double rk_m = measured_stable_step(scene, "rk4", rk, halvings, steps);
      table.add_row({format("%d x %d", n, n), format("%.0e", K), format("%.4g", lattice), format("%.4g", cloth_omega),
                     format("%.3g / %.3g", se, se_m), format("%.3g / %.3g", rk, rk_m)});
      worst[0] = std::max(worst[0], std::abs(se_m / se - 1));
      worst[1] = std::max(worst[1], std::abs(rk_m / rk - 1));
      dat += format("%d %g %.6g %.6g %.6g %.6g %.6g %.6g\n", n, K, lattice, cloth_omega, se, se_m, rk, rk_m);
      std::printf("stable step %dx%d K %g: omega lattice %.4g cloth %.4g; SE %.3g/%.3g RK4 %.3g/%.3g\n", n, n, K,
                  lattice, cloth_omega, se, se_m, rk, rk_m);
    }
  }
  write_table_fragment(s.out + "/stable_step.md", table, s.command);
  write_text_fragment(s.out + "/stable_step_agreement.md",
                      format("The prediction holds to %.1f %% for symplectic Euler and to %.1f %% for RK4.",
                             100 * worst[0], 100 * worst[1]));
  ch10::write_text(s.out, "stable_step.dat", dat);
}

// ---------------------------------------------------------------------------------------------------------------
// Error curves: every method at its candidate steps on the 20 x 20 fabric of stiffness K, against a reference.

struct Measurement {
  std::string method;
  double h = 0;
  long long steps = 0;
  double seconds = 0, error = 0;
  bool ok = true;
  std::string message;
  StepCounters counters;
};

struct Curves {
  double K = 0, T = 0;
  long long reference_steps = 0;
  double reference_agreement = -1;  ///< RK4 against the 3/8 rule, when checked
  double displacement = 0;          ///< the reference's largest distance of a particle from its rest position at T
  std::vector<Measurement> rows;
};

/// Prints one sweep's reference and every run of it, as the progress of the program.
void print_curves(const Curves& c) {
  const std::string check = c.reference_agreement < 0 ? "not checked against the 3/8 rule"
                                                       : "3/8 rule at twice as many: " + format_number(c.reference_agreement, 3) + " m";
  std::printf("K %g, T %g: reference RK4 with %lld steps (%s)\n", c.K, c.T, c.reference_steps, check.c_str());
  for (const Measurement& m : c.rows)
    std::printf("  %-20s h %-10.4g steps %-7lld %8.4f s  error %.3e %s\n", m.method.c_str(), m.h, m.steps, m.seconds,
                m.error, m.ok ? "" : m.message.c_str());
}

// [sweep]
// Every method at its candidate steps: explicit methods from 95 % of their predicted stable step downwards, implicit ones from one step per 1/30 s frame downwards, each halving
// until the error at T is below 0.5 mm, a run costs more than `budget` CPU seconds, or `max_halvings` halvings.
// Runs shorter than budget / 4 are repeated and timed by their fastest run (ch10::run_to).
Curves error_curves(double K, double T, const std::vector<std::string>& methods, bool check_reference, double budget,
                    int max_halvings, double reference_division) {
  const SceneParams p = ch10::fabric(20, K);
  const Scene scene(p);
  const double omega = lattice_fastest_frequency({K, K, K, p.mass});
  Curves c{K, T, 0, -1, 0, {}};
  // The reference: RK4 at a quarter of its stable step (a third in the quick run; RK4 at the stable step itself is
  // within ~1e-7 m of it, measured below), checked in the full run against the 3/8 rule, a different fourth-order
  // method, at half that step.
  c.reference_steps = static_cast<long long>(std::ceil(T / (2 * std::sqrt(2.0) / omega / reference_division)));
  const Vector ref = ch10::reference(scene, T, c.reference_steps, check_reference, c.reference_agreement);
  c.displacement = largest_distance(ref, scene.initial_positions());
  for (const std::string& method : methods) {
    long long steps = 0;
    if (ch10::is_explicit(method)) {
      // 95 % of the predicted stable step: as large as stability allows, with a margin for the sagged state.
      steps = static_cast<long long>(std::ceil(T / (0.95 * stability_reach(method) / omega)));
    } else {
      steps = std::llround(T * 30);
    }
    for (int k = 0; k <= max_halvings; ++k, steps *= 2) {
      const ch10::Run r = ch10::run_to(scene, method, T, steps, budget / 4);
      Measurement m{method, T / static_cast<double>(steps), steps, r.seconds, NAN, r.ok, r.message, r.counters};
      if (r.ok) m.error = largest_distance(r.x, ref);
      c.rows.push_back(m);
      if ((r.ok && m.error < 5e-4) || r.seconds > budget) break;
    }
  }
  return c;
}
// [sweep]

// The cheapest run of `method` whose error at T is below tol (nullptr when none).
const Measurement* cheapest(const std::vector<Measurement>& rows, const std::string& method, double tol) {
  const Measurement* best = nullptr;
  for (const Measurement& m : rows)
    if (m.method == method && m.ok && m.error <= tol && (best == nullptr || m.seconds < best->seconds)) best = &m;
  return best;
}

void write_curves(const Settings& s, const Curves& c, const std::string& tag) {
  std::string dat = "# method h steps cpu_seconds error_at_T rhs factorizations linear_solves cg_iterations "
                    "newton_iterations status (one block per method)\n";
  std::string last;
  for (const Measurement& m : c.rows) {
    if (m.method != last && !last.empty()) dat += "\n\n";
    last = m.method;
    dat += format("%s %.6e %lld %.6e %.6e %lld %lld %lld %lld %lld %s\n", m.method.c_str(), m.h, m.steps, m.seconds,
                  m.error, m.counters.rhs_evaluations, m.counters.factorizations, m.counters.linear_solves,
                  m.counters.cg_iterations, m.counters.newton_iterations, m.ok ? "ok" : "failed");
  }
  ch10::write_text(s.out, "curves_" + tag + ".dat", dat);
}

// ---------------------------------------------------------------------------------------------------------------
// The practitioner's question: what each method costs to reach 1 cm and 1 mm at T.

void practitioner(const Settings& s, const Curves& c, const std::vector<std::string>& methods, std::string& summary) {
  const std::string tag = format("T%g", c.T);
  write_curves(s, c, "practitioner_" + tag);
  MarkdownTable table({"method", "1 cm: step h [s]", "steps", "CPU time [s]", "error [m]", "1 mm: step h [s]", "steps",
                       "CPU time [s]", "error [m]"},
                      "lrrrrrrrr");
  for (const std::string& method : methods) {
    std::vector<std::string> row = {ch10::label(method)};
    for (double tol : {1e-2, 1e-3}) {
      const Measurement* m = cheapest(c.rows, method, tol);
      for (const std::string& cell : m == nullptr ? std::vector<std::string>{"-", "-", "-", "-"}
                                                  : std::vector<std::string>{ch10::step_text(m->h), format("%lld", m->steps),
                                                                             format("%.3g", m->seconds),
                                                                             format("%.2g", m->error)})
        row.push_back(cell);
    }
    table.add_row(row);
  }
  write_table_fragment(s.out + "/practitioner_" + tag + ".md", table, s.command);
  std::string note = format("Reference: RK4 with %lld steps", c.reference_steps);
  if (c.reference_agreement >= 0)
    note += format("; the 3/8 rule with twice as many steps agrees with it to %.1e m", c.reference_agreement);
  note += format(". At T the farthest particle is %.3g m from its rest position. A dash: no step tried reached the "
                 "accuracy.", c.displacement);
  write_text_fragment(s.out + "/practitioner_" + tag + "_note.md", note);
  write_text_fragment(s.out + "/displacement_" + tag + ".md", format("%.3g m", c.displacement));
  // [verdict]
  // The fastest explicit and the fastest implicit run that reached each accuracy, in one sentence each.
  for (double tol : {1e-2, 1e-3}) {
    const Measurement* best_explicit = nullptr;
    const Measurement* best_implicit = nullptr;
    for (const std::string& method : methods) {
      const Measurement* m = cheapest(c.rows, method, tol);
      if (m == nullptr) continue;
      const Measurement*& slot = ch10::is_explicit(method) ? best_explicit : best_implicit;
      if (slot == nullptr || m->seconds < slot->seconds) slot = m;
    }
    const auto run = [](const Measurement* m) {
      return format("%s at h = %s (%lld steps), %.3g s, error %.2g m", ch10::label(m->method).c_str(),
                    ch10::step_text(m->h).c_str(), m->steps, m->seconds, m->error);
    };
    const std::string accuracy = tol == 1e-2 ? "1 cm" : "1 mm";
    std::string sentence;
    if (best_explicit && best_implicit) {
      const bool implicit_wins = best_implicit->seconds < best_explicit->seconds;
      const Measurement* winner = implicit_wins ? best_implicit : best_explicit;
      const Measurement* other = implicit_wins ? best_explicit : best_implicit;
      sentence = format("To %s the fastest run is %s; the fastest %s one is %s, %.1f times as long.", accuracy.c_str(),
                        run(winner).c_str(), implicit_wins ? "explicit" : "implicit", run(other).c_str(),
                        other->seconds / winner->seconds);
    } else if (best_explicit || best_implicit) {
      sentence = format("To %s the fastest run is %s; no %s run tried got there.", accuracy.c_str(),
                        run(best_explicit ? best_explicit : best_implicit).c_str(),
                        best_explicit ? "implicit" : "explicit");
    } else {
      sentence = "No run tried got to " + accuracy + ".";
    }
    summary += format("T = %g s: %s\n", c.T, sentence.c_str());
    write_text_fragment(s.out + format("/verdict_%s_%s.md", tag.c_str(), tol == 1e-2 ? "1cm" : "1mm"), sentence);
  }
  // [verdict]
}

// ---------------------------------------------------------------------------------------------------------------
// The map: the cheapest method over resolution and stiffness, from a cost model.

// [step_cost]
// CPU seconds per step on the n x n fabric (K = 1e5, from rest; steps of 1/60 s for implicit methods, 1e-6 s for
// explicit ones, inside their stability limit at every size), the best of three runs.
double measure_step_cost(int n, const std::string& method, int steps) {
  const Scene scene(ch10::fabric(n, 1e5));
  const double h = ch10::is_explicit(method) ? 1e-6 : 1.0 / 60;
  double best = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const ch10::Run r = ch10::run_to(scene, method, steps * h, steps, 0);
    best = std::min(best, r.seconds / static_cast<double>(steps));
  }
  return best;
}
// [step_cost]

// The method whose measured step cost stands for `method`'s growth with the grid: full Newton costs what its
// iterations cost, one iteration's cost grows like a single-iteration step's, and every local/global iteration
// count grows like 10 iterations.
std::string cost_proxy(const std::string& method) {
  if (method == "implicit_euler/exact") return "implicit_euler/one/exact";
  if (method == "implicit_euler/cg") return "implicit_euler/one/cg";
  if (method.rfind("local_global", 0) == 0) return "local_global";
  return method;
}

struct SizeCost {
  double seconds = 0;
  bool measured = false;
};

void map(const Settings& s, const std::map<double, Curves>& curves, const std::vector<std::string>& methods) {
  const std::vector<int> sizes = {20, 39, 77, 153};
  const auto springs = [](int n) {
    double total = 0;
    for (SpringFamily f : all_spring_families) total += spring_count(f, n, n);
    return total;
  };
  // 1. Cost per step against the grid: measured where affordable, beyond that extrapolated as a power of the
  //    number of springs fitted to the two largest measured sizes.
  std::map<std::string, std::map<int, SizeCost>> cost;
  std::vector<std::string> header = {"method"};
  for (int n : sizes) header.push_back(format("%d x %d", n, n));
  header.emplace_back("exponent");
  MarkdownTable cost_md(header, "lrrrrr");
  std::string cost_dat = "# method n springs seconds_per_step measured\n";
  for (const char* name : {"symplectic_euler", "rk4", "implicit_euler/one/exact", "implicit_euler/one/cg", "local_global"}) {
    const std::string method = name;
    const bool direct = method == "implicit_euler/one/exact";
    std::vector<int> measured;
    for (int n : sizes) {
      // The quick run measures up to 77 x 77 (39 x 39 for the direct solve, whose factorization is the slowest).
      if (n > (s.quick ? (direct ? 39 : 77) : (direct ? 77 : 153))) continue;
      const int steps = ch10::is_explicit(method) ? (n > 40 ? 20 : 200) : (n > 40 ? 2 : 10);
      cost[method][n] = {measure_step_cost(n, method, steps), true};
      measured.push_back(n);
    }
    const int a = measured[measured.size() - 2], b = measured.back();
    const double exponent =
        std::log(cost[method][b].seconds / cost[method][a].seconds) / std::log(springs(b) / springs(a));
    for (int n : sizes)
      if (!cost[method][n].measured)
        cost[method][n] = {cost[method][b].seconds * std::pow(springs(n) / springs(b), exponent), false};
    std::vector<std::string> row = {ch10::label(method)};
    for (int n : sizes) {
      row.push_back(format("%.3g ms%s", 1e3 * cost[method][n].seconds, cost[method][n].measured ? "" : " (predicted)"));
      cost_dat += format("%s %d %.0f %.6e %d\n", method.c_str(), n, springs(n), cost[method][n].seconds,
                         cost[method][n].measured ? 1 : 0);
    }
    row.push_back(format("%.2f", exponent));
    cost_md.add_row(row);
    cost_dat += "\n\n";
    std::printf("cost per step %s: exponent %.2f over %d..%d\n", method.c_str(), exponent, a, b);
  }
  write_table_fragment(s.out + "/step_cost.md", cost_md, s.command);
  ch10::write_text(s.out, "step_cost.dat", cost_dat);

  // [cost_model]
  // cost[method][n]: the CPU seconds of one step on the n x n fabric, measured at K = 1e5 N/m (or extrapolated
  // from the two largest measured sizes: the step-cost table) and used for every K; cost_proxy(method) names the
  // method whose step stands for this one's (one Newton iteration's for full Newton's, 10 local/global
  // iterations' for any number).
  // 2. Predicted CPU time of each method on the n x n fabric of stiffness K to reach a tolerance: its cheapest run
  //    that reached it on the 20 x 20 fabric (same K), with the time per step scaled by the measured growth of a
  //    step with the grid and, for an explicit method, the number of steps scaled by omega_max(n) / omega_max(20):
  //    its stable step shrinks with the spacing. An implicit method keeps its step, because the motion of the
  //    same square metre converges as the grid is refined (the refinement study).
  const auto predicted = [&](const Measurement& m, int n, double K) {
    double steps = static_cast<double>(m.steps);
    if (ch10::is_explicit(m.method))
      steps *= lattice_fastest_frequency({K, K, K, ch10::fabric(n, K).mass}) /
               lattice_fastest_frequency({K, K, K, ch10::fabric(20, K).mass});
    const std::string proxy = cost_proxy(m.method);
    return m.seconds / static_cast<double>(m.steps) * cost[proxy][n].seconds / cost[proxy][20].seconds * steps;
  };
  // [cost_model]
  std::string dat = "# tol K n method predicted_cpu_seconds\n";
  std::vector<std::string> map_header = {"K [N/m]"};
  for (int n : sizes) map_header.push_back(format("%d x %d", n, n));
  MarkdownTable md[2] = {MarkdownTable(map_header, "lllll"), MarkdownTable(map_header, "lllll")};
  const double tols[2] = {1e-2, 1e-3};
  int winner_index = 0;
  std::map<std::string, int> winner_code;
  std::string winners = "# tol K n winner_code winner predicted_seconds runner_up_ratio\n";
  for (const auto& [K, c] : curves) {
    if (c.T != 0.5) continue;
    for (int t = 0; t < 2; ++t) {
      std::vector<std::string> row = {format("%.0e", K)};
      for (int n : sizes) {
        std::string best;
        double best_seconds = INFINITY, second = INFINITY;
        for (const std::string& method : methods) {
          const Measurement* m = cheapest(c.rows, method, tols[t]);
          if (m == nullptr) continue;
          const double seconds = predicted(*m, n, K);
          dat += format("%g %g %d %s %.6e\n", tols[t], K, n, method.c_str(), seconds);
          if (seconds < best_seconds) second = best_seconds, best_seconds = seconds, best = method;
          else second = std::min(second, seconds);
        }
        if (best.empty()) {
          row.emplace_back("none reached it");
          continue;
        }
        if (!winner_code.contains(best)) winner_code[best] = winner_index++;
        winners += format("%g %g %d %d %s %.6e %.6e\n", tols[t], K, n, winner_code[best], best.c_str(), best_seconds,
                          second / best_seconds);
        row.push_back(format("%s: %.3g s%s, next %.1fx", ch10::label(best).c_str(), best_seconds,
                             n == 20 ? " (measured)" : "", second / best_seconds));
      }
      md[t].add_row(row);
    }
  }
  write_table_fragment(s.out + "/map_1cm.md", md[0], s.command);
  write_table_fragment(s.out + "/map_1mm.md", md[1], s.command);
  ch10::write_text(s.out, "map.dat", dat);
  ch10::write_text(s.out, "map_winners.dat", winners);
}

// The files of a practitioner's table at T (a tag such as "T0.5").
std::vector<std::string> practitioner_files(const std::string& tag) {
  return {"practitioner_" + tag + ".md", "practitioner_" + tag + "_note.md", "displacement_" + tag + ".md",
          "verdict_" + tag + "_1cm.md", "verdict_" + tag + "_1mm.md", "curves_practitioner_" + tag + ".dat"};
}

// What only the full sweep writes: the practitioner's question over a whole second.
std::vector<std::string> full_run_only() { return practitioner_files("T1"); }

// Every file a run writes (the tables are the page's fragments).
std::vector<std::string> outputs(bool quick, bool curtain_only) {
  if (curtain_only) return ch10::curtain_outputs(!quick);
  std::vector<std::string> files = {"preset.md",        "stable_step.md",      "stable_step_agreement.md",
                                    "stable_step.dat",  "practitioner_summary.txt", "curves_K1000.dat",
                                    "curves_K10000.dat", "curves_K100000.dat", "curves_K1e+06.dat",
                                    "refinement.md",    "refinement.dat",      "fabric_frames.dat",
                                    "step_cost.md",     "step_cost.dat",       "map_1cm.md",
                                    "map_1mm.md",       "map.dat",             "map_winners.dat"};
  for (const std::string& f : practitioner_files("T0.5")) files.push_back(f);
  if (!quick)
    for (const std::string& f : full_run_only()) files.push_back(f);
  return files;
}

// The files of the other modes, removed before a run so that none is left stale beside this run's.
std::vector<std::string> other_outputs(bool quick, bool curtain_only) {
  std::vector<std::string> all = outputs(false, false), mine = outputs(quick, curtain_only), others;
  for (const std::string& f : ch10::curtain_outputs(true)) all.push_back(f);
  for (const std::string& f : all)
    if (std::find(mine.begin(), mine.end(), f) == mine.end()) others.push_back(f);
  return others;
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch10_real_cloth",
                  "Chapter 10: real cloth in physical units. Fabric preset, refinement, stable steps, the cost of\n"
                  "each method to reach 1 cm and 1 mm, and the map of the cheapest method. The scenes are the\n"
                  "chapter's own; --out says where the tables and data go.");
  cli.use_common({"--out"});
  Settings s;
  cli.add_switch("--quick", "a reduced sweep for the plots target (under a minute)", [&] { s.quick = true; });
  cli.add_switch("--curtain", "instead, the study of cloth that moves (the curtain)", [&] { s.curtain_only = true; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    prepare_outputs(opt.run.out_dir, outputs(s.quick, s.curtain_only), other_outputs(s.quick, s.curtain_only));
    s.out = opt.run.out_dir;
    s.command = reader_command(argc, argv);
    if (s.curtain_only) {
      ch10::curtain_study(s.quick, s.out, s.command);
      return 0;
    }
    write_table_fragment(s.out + "/preset.md", preset_table(), s.command);
    // [methods]
    const std::vector<double> stiffnesses = {1e3, 1e4, 1e5, 1e6};
    const std::vector<std::string> methods = {"symplectic_euler",  "rk4",           "implicit_euler/exact",
                                              "implicit_euler/one/exact", "implicit_euler/one/cg", "implicit_euler/cg",
                                              "local_global",   "local_global/50it"};
    // [methods]
    stable_steps(s, stiffnesses);
    std::map<double, Curves> curves;
    const double budget = s.quick ? 0.08 : 2.0;
    const int halvings = s.quick ? 4 : 7;
    const double division = s.quick ? 3 : 4;
    for (double K : stiffnesses) {
      curves[K] = error_curves(K, 0.5, methods, !s.quick && K <= 1e5, budget, halvings, division);
      print_curves(curves[K]);
    }
    std::string summary;
    practitioner(s, curves[1e5], methods, summary);
    if (!s.quick) {
      const Curves long_run = error_curves(1e5, 1.0, methods, true, budget, halvings, division);
      print_curves(long_run);
      practitioner(s, long_run, methods, summary);
    }
    std::fputs(summary.c_str(), stdout);
    ch10::write_text(s.out, "practitioner_summary.txt", summary);
    for (const auto& [K, c] : curves) write_curves(s, c, format("K%g", K));
    refinement(s);
    map(s, curves, methods);
    return 0;
  });
}
