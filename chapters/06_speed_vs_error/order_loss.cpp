// Chapter 6: what springs passing near zero length do to the methods' orders. The local error of RK4 step by step
// beside the shortest spring tells where the error is made; successive step halvings tell the observed order
// over a short horizon (before the fold) and a long one (through it), with no reference solution needed.
#include "page_text.hpp"
#include "studies.hpp"

#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "program/fragment.hpp"

#include "integrators/method_registry.hpp"
#include "program/interrupt.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ch06 {

using namespace cloth;

std::string local_error_name(double h) { return "local_error_h" + std::to_string(std::lround(1e6 * h)) + "us.dat"; }

// [local_error]
// Along one RK4 run with step h, from every state: one step of h and two steps of h/2. Their difference times
// 16/15 estimates the local error of the h-step (Richardson: a fourth-order step's error scales as h^5, so
// e(h) - e(h/2) pairs ~ (1 - 2/32) e(h)). Where the right-hand side is smooth it is ~ C h^5. The model it is
// compared with: a structural spring passing through zero length reverses its force K (L0 - l) u ~ K L0 u, a
// jump of J = 2 K L0 / m in a particle's acceleration inside one step. A step that does not resolve the instant
// of the jump misweights it whatever its order: across a jump, one RK4 step against two half steps differ by up
// to J h / 4 in velocity and J h^2 / 6 in position (times 16/15 here), at the worst instant of the jump.
LocalError local_error_along_trajectory(const SceneParams& base, double T, double h, const Sink& sink) {
  const Scene scene(base);
  ForceField field(scene);
  const auto rk4 = make_stepper("rk4", field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  Vector x_full(x.size()), v_full(x.size()), x_half(x.size()), v_half(x.size());
  Vector all(3 * scene.particle_count());
  const auto file = open(sink, local_error_name(h),
                      "# t local_position_error_m local_velocity_error_m_per_s shortest_spring_l_over_L0  (rk4)");
  std::FILE* const f = file->get();
  const double jump = 2 * scene.stiffness(SpringFamily::structural) * base.grid.d / base.mass;
  const auto steps = static_cast<long long>(std::llround(T / h));
  double worst = 0, t_worst = 0, worst_velocity = 0;
  long long jump_steps = 0;
  std::vector<double> smooth;  // the local errors of the steps without a jump
  for (long long k = 0; k < steps; ++k) {
    throw_if_interrupted();
    x_full = x, v_full = v;
    rk4->step(h, x_full, v_full);
    x_half = x, v_half = v;
    rk4->step(0.5 * h, x_half, v_half);
    rk4->step(0.5 * h, x_half, v_half);
    const double local = 16.0 / 15.0 * largest_distance(x_full, x_half);
    const double local_velocity = 16.0 / 15.0 * largest_distance(v_full, v_half);
    const double t = static_cast<double>(k) * h;
    std::fprintf(f, "%.6f %.6e %.6e %.6e\n", t, local, local_velocity,
                 shortest_spring(scene, x, all).length_over_rest);
    if (local > worst) worst = local, t_worst = t;
    worst_velocity = std::max(worst_velocity, local_velocity);
    if (local_velocity > 0.01 * jump * h)  // an error of the jump's size, not of a smooth step's
      ++jump_steps;
    else
      smooth.push_back(local);
    x = x_half, v = v_half;  // continue on the more accurate branch
  }
  file->commit();
  std::printf("local error of rk4 (K %g, D %g, h %g): largest %.3e m at t = %.4f s (model J h^2/6 = %.3e), velocity "
              "%.3e m/s (model J h/4 = %.3e), J = %g m/s^2, models times 16/15 at worst; %lld of %lld steps with velocity error > 0.01 J h\n",
              base.stiffness, base.damping, h, worst, t_worst, jump * h * h / 6, worst_velocity, jump * h / 4, jump,
              jump_steps, steps);
  std::fprintf(sink.table, "local_error K%g_D%g rk4 %.6g %lld - %.6e %.6e - - - - - ok\n", base.stiffness,
               base.damping, h, steps, worst, worst_velocity);
  std::nth_element(smooth.begin(), smooth.begin() + static_cast<long>(smooth.size() / 2), smooth.end());
  return {h, jump, steps, jump_steps, worst, worst_velocity, smooth.empty() ? 0.0 : smooth[smooth.size() / 2]};
}
// [local_error]

// [observed_orders]
// Observed order without a reference: with d_k = max over particles |x_{h_k}(T) - x_{h_k / 2}(T)| and
// h_k = T / 2^k, d_k ~ C h_k^p, so p ~ log2(d_k / d_{k+1}) wherever the error is in its asymptotic regime.
std::vector<ObservedOrder> observed_orders(const SceneParams& base, const OrderLadder& ladder, const Sink& sink) {
  const Scene scene(base);
  std::vector<ObservedOrder> out;
  const auto file = open(sink, "orders.dat",
                      "# method T h difference_to_half_step observed_order  (blocks by method and T)");
  std::FILE* const f = file->get();
  for (const char* method : {"explicit_euler", "symplectic_euler", "heun", "rk4"}) {
    for (const double T : ladder.horizons) {
      std::fprintf(f, "# %s T = %g\n", method, T);
      ForceField field(scene);
      auto stepper = make_stepper(method, field);
      Vector previous;
      double previous_difference = 0;
      for (int k = ladder.k_min; k <= ladder.k_max + 1; ++k) {
        const Trajectory run = run_sampled(*stepper, T, 1LL << k, 1);
        if (!run.ok) {  // diverged: no difference to take, and the next one has no predecessor
          previous.resize(0);
          previous_difference = 0;
          continue;
        }
        if (previous.size() > 0) {
          const double h = T / static_cast<double>(1LL << (k - 1));
          const double difference = largest_distance(previous, run.x.back());
          const double order = previous_difference > 0 ? std::log2(previous_difference / difference) : NAN;
          out.push_back({method, T, h, difference, order});
          std::fprintf(f, "%s %g %.6e %.6e %.3f\n", method, T, h, difference, order);
          std::fprintf(sink.table, "observed_order K%g_D%g %s %.6g %lld - %.6e %.3f - - - - - ok\n",
                       base.stiffness, base.damping, method, h, 1LL << (k - 1), difference, order);
          previous_difference = difference;
        }
        previous = run.x.back();
      }
      std::fprintf(f, "\n\n");
    }
  }
  file->commit();
  return out;
}
// [observed_orders]

void write_order_loss_fragments(const std::string& dir, const std::vector<LocalError>& local_errors,
                                const std::vector<ObservedOrder>& orders, const std::string& command) {
  MarkdownTable jumps({"h [s]", "steps with a jump", "velocity error [m/s]", "16/15 J h / 4", "position error [m]",
                       "16/15 J h^2 / 6"},
                      "rrrrrr");
  for (const LocalError& e : local_errors)
    jumps.add_row({g(e.h), std::to_string(e.jump_steps) + " of " + std::to_string(e.steps), g(e.worst_velocity, 4),
                   g(16.0 / 15.0 * e.jump * e.h / 4, 4), g(e.worst_position, 4),
                   g(16.0 / 15.0 * e.jump * e.h * e.h / 6, 4)});
  write_table_fragment(dir + "/jumps.md", jumps, command);
  std::string sentence;
  for (const LocalError& e : local_errors)
    if (std::abs(e.h - 1e-3) < 1e-12)
      sentence = "With h = 1e-3 s, a step without a jump makes a local error of about " + g(e.smooth_median) +
                 " m (the median over the run); " + std::to_string(e.jump_steps) + " of the " +
                 std::to_string(e.steps) + " steps are different: their errors reach " + g(e.worst_position) +
                 " m, " + sci(e.worst_position / e.smooth_median, 1) + " times more.\n";
  write_text_fragment(dir + "/local_error.md", sentence);

  // Observed orders from successive halvings: one row per method and horizon, one column per step h = T / division.
  std::vector<long long> divisions;
  std::vector<std::pair<std::string, double>> rows;
  for (const ObservedOrder& o : orders) {
    if (const long long d = std::llround(o.T / o.h); std::find(divisions.begin(), divisions.end(), d) == divisions.end())
      divisions.push_back(d);
    if (std::find(rows.begin(), rows.end(), std::make_pair(o.method, o.T)) == rows.end()) rows.emplace_back(o.method, o.T);
  }
  std::sort(divisions.begin(), divisions.end());
  std::vector<std::string> header = {"method", "T [s]", "difference at h = T/" + std::to_string(divisions.front())};
  for (std::size_t i = 1; i < divisions.size(); ++i) header.push_back("order at T/" + std::to_string(divisions[i]));
  header.push_back("difference at T/" + std::to_string(divisions.back()));
  MarkdownTable table(header, std::string("l").append(header.size() - 1, 'r'));
  for (const auto& [method, T] : rows) {
    std::vector<std::string> row = {method_title(method), g(T), "-"};
    std::vector<std::string> order_cells(divisions.size() - 1, "-");
    std::string last = "-";
    for (const ObservedOrder& o : orders) {
      if (o.method != method || o.T != T) continue;
      const auto at = std::find(divisions.begin(), divisions.end(), std::llround(o.T / o.h)) - divisions.begin();
      if (at == 0) row[2] = g(o.difference);
      if (at > 0 && !std::isnan(o.order)) order_cells[static_cast<std::size_t>(at - 1)] = format_fixed(o.order, 2);
      if (at + 1 == static_cast<long>(divisions.size())) last = g(o.difference);
    }
    row.insert(row.end(), order_cells.begin(), order_cells.end());
    row.push_back(last);
    table.add_row(row);
  }
  write_table_fragment(dir + "/observed_orders.md", table, command);
}

}  // namespace ch06
