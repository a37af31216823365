// Random states of a scene for the finite-difference checks of forces and Jacobians.
#pragma once

#include "model/force_field.hpp"

#include <limits>
#include <random>

namespace cloth::testing {

/// u = 2^-53, the unit roundoff of double: the rounding term of every finite-difference error bound.
constexpr double unit_roundoff = std::numeric_limits<double>::epsilon() / 2;

struct State {
  Vector x, v;
};

/// The rest grid scaled in-plane by `scale` about the origin (< 1 compresses, > 1 stretches), every coordinate
/// moved by up to `jitter` d, velocities uniform in [-speed, speed]. Pinned particles stay at rest, as always.
inline State random_state(const Scene& scene, std::mt19937& rng, double scale, double jitter, double speed) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  State s{scene.initial_positions(), Vector(scene.dof_count())};
  for (Eigen::Index k = 0; k < s.x.size(); ++k) {
    if (k % 3 != 2) s.x[k] *= scale;
    s.x[k] += jitter * scene.grid().d * unit(rng);
    s.v[k] = speed * unit(rng);
  }
  return s;
}

}  // namespace cloth::testing
