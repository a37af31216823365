// Chapter 6: how fast nearby solutions separate. Two RK4 runs a perturbation apart on each configuration of the
// sweep; the ratio of their distance to the perturbation is the condition number of the solution at time t.
#include "page_text.hpp"
#include "studies.hpp"

#include "analysis/trajectory_measures.hpp"
#include "integrators/method_registry.hpp"
#include "model/report_cases.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <algorithm>
#include <cmath>

namespace ch06 {

using namespace cloth;

// [sensitivity]
// Two RK4 runs whose initial positions differ by 1e-12 m in one coordinate (a particle near the middle, in z):
// the ratio of their largest particle distance to 1e-12 is how much the problem amplifies a perturbation, the
// condition number of the solution at time t; no method can be checked more accurately than eps times it.
std::vector<Sensitivity> sensitivity(const SceneParams& base, const std::vector<Config>& configs, double h,
                                     const Sink& sink) {
  const auto file = open(sink, "sensitivity.dat", "# config K D t amplification  (blocks by config)");
  std::FILE* const f = file->get();
  const double delta = 1e-12;
  std::vector<Sensitivity> out;
  for (const Config& c : configs) {
    Sensitivity& series = out.emplace_back(Sensitivity{c.name, {}, {}});
    const Scene scene(with_K_and_D(base, c.K, c.D));
    ForceField fa(scene), fb(scene);
    const auto a = make_stepper("rk4", fa), b = make_stepper("rk4", fb);
    Vector xa = scene.initial_positions(), va = scene.initial_velocities();
    Vector xb = xa, vb = va;
    xb[3 * (scene.free_count() / 2) + 2] += delta;
    const double T = 1.0;
    const auto steps = static_cast<long long>(std::llround(T / h));
    const long long every = std::max(1LL, steps / 200);
    std::fprintf(f, "# %s\n", c.name.c_str());
    for (long long k = 0; k <= steps; ++k) {
      throw_if_interrupted();
      if (k > 0) a->step(h, xa, va), b->step(h, xb, vb);
      if (k % every != 0) continue;
      const double t = static_cast<double>(k) * h, amp = largest_distance(xa, xb) / delta;
      series.t.push_back(t), series.amplification.push_back(amp);
      std::fprintf(f, "%s %g %g %.6f %.6e\n", c.name.c_str(), c.K, c.D, t, amp);
      std::fprintf(sink.table, "sensitivity %s - %.6f - - - %.6e - - - - - ok\n", c.name.c_str(), t, amp);
    }
    std::fprintf(f, "\n\n");
  }
  file->commit();
  return out;
}
// [sensitivity]

void write_sensitivity_fragment(const std::string& dir, const std::vector<Sensitivity>& s,
                                const std::vector<Config>& configs, const std::string& command) {
  MarkdownTable table({"(K, D)", "largest for t <= 0.25 s", "largest for t <= 0.5 s", "at t = 1 s",
                       "first above 100 at", "first above 1e6 at"},
                      "lrrrrr");
  for (std::size_t c = 0; c < s.size() && c < configs.size(); ++c) {
    double up_to_quarter = 0, up_to_half = 0;
    std::string above_100 = "never", above_million = "never";
    for (std::size_t i = 0; i < s[c].t.size(); ++i) {
      const double t = s[c].t[i], a = s[c].amplification[i];
      if (t <= 0.25 + 1e-12) up_to_quarter = std::max(up_to_quarter, a);
      if (t <= 0.5 + 1e-12) up_to_half = std::max(up_to_half, a);
      if (above_100 == "never" && a > 100) above_100 = "t = " + g(t, 3) + " s";
      if (above_million == "never" && a > 1e6) above_million = "t = " + g(t, 3) + " s";
    }
    const auto amplification = [](double a) { return a < 1e4 ? whole_or(a, 2) : g(a, 2); };
    table.add_row({config_title(configs[c]), amplification(up_to_quarter), amplification(up_to_half),
                   amplification(s[c].amplification.back()), above_100, above_million});
  }
  write_table_fragment(dir + "/sensitivity.md", table, command);
}

}  // namespace ch06
