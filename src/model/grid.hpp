// The rectangular particle grid of the report: M x N particles (i, j) resting at (i d, j d, 0).
#pragma once

#include <Eigen/Core>

namespace cloth {

/// An M x N grid of particles with rest spacing d; particle (i, j) rests at (i d, j d, 0), z up.
struct Grid {
  int M = 20;          ///< particles along x (index i)
  int N = 20;          ///< particles along y (index j)
  double d = 0.1;      ///< rest spacing [m]

  /// Number of particles, M N.
  [[nodiscard]] int particle_count() const { return M * N; }
  /// Particle number of (i, j), row-major in i: the order of final.dat and frames.dat.
  [[nodiscard]] int particle(int i, int j) const { return i * N + j; }
  /// Rest position of particle (i, j).
  [[nodiscard]] Eigen::Vector3d rest_position(int i, int j) const { return {i * d, j * d, 0.0}; }
};

}  // namespace cloth
