// The small moving cloth the tests of the frame-rate methods (local/global, XPBD) start from: Chapter 10's light,
// stiff fabric on an 8 x 8 grid hanging from its corners, moved for a while so that a step starts bent and moving.
#pragma once

#include "integrators/symplectic_euler.hpp"
#include "model/force_field.hpp"
#include "random_state.hpp"

namespace cloth::testing {

/// 8 x 8 particles 5 cm apart, m = 6.25e-4 kg, K = 1e3 for every spring, damping D, pushed down at 0.5 m/s.
inline SceneParams light_cloth(double D) {
  SceneParams p;
  p.grid = Grid{8, 8, 0.05};
  p.mass = 6.25e-4;
  p.stiffness = 1e3;
  p.damping = D;
  p.initial_velocity_z = -0.5;
  return p;
}

/// The scene's state after 0.1 s of symplectic Euler at a stable step (h = 2.5e-5 s, 4000 steps).
inline State moving_state(const Scene& scene) {
  ForceField field(scene);
  SymplecticEuler warmup(field);
  State s{scene.initial_positions(), scene.initial_velocities()};
  for (int k = 0; k < 4000; ++k) warmup.step(2.5e-5, s.x, s.v);
  return s;
}

}  // namespace cloth::testing
