// The cloth drawn as its spring mesh: one line segment per spring with the spring's strain (l - L0) / L0, so a
// gnuplot `splot ... lc palette` shows where the cloth stretches (red) and where it is compressed (blue).
#pragma once

#include "model/scene.hpp"

#include <Eigen/Core>
#include <cmath>
#include <cstdio>

namespace ch05 {

/// Writes one gnuplot block: for every spring of `family`, its two endpoints as `x y z strain` lines followed by
/// a blank line. `positions` holds every particle in grid order (a Frame's layout, 3 per particle); springs name
/// slots, so each endpoint is looked up through the scene's slot -> particle map. The block ends with two blank
/// lines so that consecutive blocks are separate gnuplot `index` entries. `t` goes into a comment line.
inline void write_strain_block(std::FILE* out, const cloth::Scene& scene, const Eigen::VectorXd& positions, double t,
                               cloth::SpringFamily family) {
  std::fprintf(out, "# t = %.6g\n", t);
  const cloth::SpringRange r = scene.springs().family[static_cast<int>(family)];
  for (int k = r.begin; k < r.end; ++k) {
    const cloth::Spring& s = scene.springs().springs[static_cast<std::size_t>(k)];
    const Eigen::Vector3d p = positions.segment<3>(3 * scene.particle_of_slot(s.p));
    const Eigen::Vector3d q = positions.segment<3>(3 * scene.particle_of_slot(s.q));
    const double strain = ((p - q).norm() - s.rest_length) / s.rest_length;
    std::fprintf(out, "%.6g %.6g %.6g %.4g\n%.6g %.6g %.6g %.4g\n\n", p[0], p[1], p[2], strain, q[0], q[1], q[2],
                 strain);
  }
  std::fprintf(out, "\n");
}

/// Largest |strain| over the springs of a configuration (all families), for the summary table.
inline double max_abs_strain(const cloth::Scene& scene, const Eigen::VectorXd& positions) {
  double worst = 0;
  for (const cloth::Spring& s : scene.springs().springs) {
    const Eigen::Vector3d p = positions.segment<3>(3 * scene.particle_of_slot(s.p));
    const Eigen::Vector3d q = positions.segment<3>(3 * scene.particle_of_slot(s.q));
    const double strain = std::abs(((p - q).norm() - s.rest_length) / s.rest_length);
    if (strain > worst) worst = strain;
  }
  return worst;
}

}  // namespace ch05
