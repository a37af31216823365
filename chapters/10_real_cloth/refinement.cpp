// Chapter 10's refinement study: the same square metre of fabric with 20, 39 (and 77, 153) particles per side,
// each followed by RK4 just inside its stable step, and every grid's positions compared with the next finer one's
// at the same times (the motion converges as the grid is refined).
#include "real_cloth.hpp"

#include "analysis/lattice_frequency.hpp"
#include "model/fabric.hpp"
#include "program/fragment.hpp"
#include "program/timing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace cloth;

namespace ch10 {

namespace {

// [refinement]
// RK4 at 90 % of its stable step (within ~1e-7 m of the exact motion, the practitioner's table shows) on the
// fabric preset with n particles per side; the positions of every particle at t = k T / snapshots,
// k = 0..snapshots.
std::vector<Vector> fabric_motion(int n, double T, int snapshots, long long& steps, double& seconds) {
  const SceneParams p = fabric_scene(FabricMeasurements{}, {0.95, n, 20.0});
  const Scene scene(p);
  ForceField field(scene);
  auto rk4 = make_method("rk4", field);
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

}  // namespace

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
  write_text(s.out, "refinement.dat", dat);
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
  write_text(s.out, "fabric_frames.dat", frames);
}

}  // namespace ch10
