// An independent reference motion for the measures of trajectory_measures.hpp (Chapter 10): the scene integrated
// by Chapter 8's adaptive Dormand-Prince pair at a tight tolerance, each frame interval integrated to its end
// exactly, so that the recorded frames carry no interpolation error.
#pragma once

#include "integrators/simulate.hpp"

#include <atomic>
#include <vector>

namespace cloth {

/// A reference motion: the cloth at t = k T / frames, k = 0..frames, with its energy there.
struct ReferenceTrajectory {
  std::vector<Frame> frames;
  std::vector<Energy> energy;
  long long steps = 0;      ///< accepted steps of the pair
  long long rejected = 0;   ///< rejected attempts
  double smallest_step = 0;
};

/// Integrates `field`'s scene from (x0, v0) (free particles) to T with dopri5 under the max-norm tolerances rtol = atol =
/// `tolerance` (positions in m, velocities in m/s), one adaptive run per frame interval. Throws std::runtime_error
/// naming the frame when the pair fails (a step size too small, a divergence), and stops between two attempts when
/// `stop` is raised (the result then ends at the last whole frame).
[[nodiscard]] ReferenceTrajectory reference_trajectory(ForceField& field, const Vector& x0, const Vector& v0, double T,
                                                       int frames, double tolerance,
                                                       const std::atomic<int>* stop = nullptr);

}  // namespace cloth
