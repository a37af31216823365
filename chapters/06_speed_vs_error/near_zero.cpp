// Chapter 6: where springs pass near zero length. Along an RK4 run, the smallest spring length relative to rest
// over the cloth at every step, and where and when it was smallest.
#include "page_text.hpp"
#include "studies.hpp"

#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <cmath>

namespace ch06 {

using namespace cloth;

ShortestSpring shortest_spring(const Scene& scene, const Vector& x, Vector& all) {
  scene.all_positions(x, all);
  ShortestSpring out;
  const auto& springs = scene.springs().springs;
  for (int s = 0; s < static_cast<int>(springs.size()); ++s) {
    const Spring& sp = springs[static_cast<std::size_t>(s)];
    const int p = scene.particle_of_slot(sp.p), q = scene.particle_of_slot(sp.q);
    const double l = (all.segment<3>(3 * p) - all.segment<3>(3 * q)).norm() / sp.rest_length;
    if (l < out.length_over_rest) out.length_over_rest = l, out.spring = s;
  }
  return out;
}

namespace {

// The family of spring s (0 structural, 1 shear, 2 flexion).
int family_of(const SpringSet& springs, int s) {
  for (SpringFamily fam : all_spring_families)
    if (s >= springs.family[static_cast<int>(fam)].begin && s < springs.family[static_cast<int>(fam)].end)
      return static_cast<int>(fam);
  return 0;
}

// "a structural spring, (9,7)-(10,7)": its family and the grid indices of its two particles.
std::string spring_description(const Scene& scene, int s) {
  const Spring& sp = scene.springs().springs[static_cast<std::size_t>(s)];
  const int p = scene.particle_of_slot(sp.p), q = scene.particle_of_slot(sp.q), N = scene.grid().N;
  const char* const names[] = {"structural", "shear", "flexion"};
  return std::string("a ") + names[family_of(scene.springs(), s)] + " spring, (" + std::to_string(p / N) + "," +
         std::to_string(p % N) + ")-(" + std::to_string(q / N) + "," + std::to_string(q % N) + ")";
}

}  // namespace

// [near_zero]
// The smallest spring length relative to rest, l / L0, over the cloth and over time: where and when springs pass
// near zero length, where the force direction u = d / l turns abruptly and the right-hand side is not smooth.
NearZero near_zero_springs(const SceneParams& base, double T, double h, const Sink& sink) {
  const Scene scene(base);
  ForceField field(scene);
  const auto rk4 = make_stepper("rk4", field);
  Vector x = scene.initial_positions(), v = scene.initial_velocities();
  Vector all(3 * scene.particle_count());
  const auto steps = static_cast<long long>(std::llround(T / h));
  const auto file = open(sink, "near_zero.dat", "# t min_l_over_L0 family(0 structural,1 shear,2 flexion) i_p j_p i_q j_q");
  std::FILE* const f = file->get();
  NearZero out;
  out.h = h;
  int spring_min = -1;
  const auto& springs = scene.springs();
  for (long long k = 0; k <= steps; ++k) {
    throw_if_interrupted();
    if (k > 0) rk4->step(h, x, v);
    const auto [worst, which] = shortest_spring(scene, x, all);
    const Spring& sp = springs.springs[static_cast<std::size_t>(which)];
    const int p = scene.particle_of_slot(sp.p), q = scene.particle_of_slot(sp.q), N = scene.grid().N;
    const double t = static_cast<double>(k) * h;
    std::fprintf(f, "%.6f %.6e %d %d %d %d %d\n", t, worst, family_of(springs, which), p / N, p % N, q / N, q % N);
    out.t.push_back(t), out.shortest.push_back(worst);
    if (worst < out.smallest) out.smallest = worst, out.t_smallest = t, spring_min = which;
    if (t <= 1.0 + 1e-12)
      std::fprintf(sink.table, "near_zero K%g_D%g - %.6f - - %.6e - - - - - - ok\n", base.stiffness, base.damping, t,
                   worst);
  }
  file->commit();
  out.spring = spring_description(scene, spring_min);
  std::printf("near-zero springs (K %g, D %g, rk4 h %g): smallest l/L0 = %.3e at t = %.4f s, %s\n", base.stiffness,
              base.damping, h, out.smallest, out.t_smallest, out.spring.c_str());
  return out;
}
// [near_zero]

void write_near_zero_fragment(const std::string& dir, const NearZero& nz) {
  const auto first_below = [&](double level) {
    for (std::size_t i = 0; i < nz.t.size(); ++i)
      if (nz.shortest[i] < level) return g(nz.t[i], 3) + " s";
    return std::string("never");
  };
  int dips = 0;
  for (std::size_t i = 1; i < nz.t.size(); ++i)
    if (nz.shortest[i] < 1e-2 && nz.shortest[i - 1] >= 1e-2) ++dips;
  write_text_fragment(dir + "/near_zero.md",
                      "In this run (RK4, h = " + g(nz.h) + " s) the shortest spring first falls below 0.5 L0 at t = " +
                          first_below(0.5) + " and below 0.1 L0 at t = " + first_below(0.1) + "; it is shortest, " +
                          sci(nz.smallest) + " L0, at t = " + g(nz.t_smallest, 3) + " s (" + nz.spring +
                          "), and dips below 0.01 L0 " + std::to_string(dips) + " times before t = " +
                          g(nz.t.back()) + " s.\n");
}

}  // namespace ch06
