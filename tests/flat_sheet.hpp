// The smallest sheet that meets a plane as a whole, shared by the contact tests that follow a step by hand: four
// particles lying flat, their springs at rest, so that every particle touches at once and stays level.
#pragma once

#include "model/scene.hpp"

#include <Eigen/Core>

namespace cloth_test {

// 2 x 2 particles at 5 cm spacing, 0.5 g each, K = 50 N/m, D = 0.1 N s/m, no pins, under gravity: the sheet lies in
// the plane z = `height` and every particle starts with the z velocity `vz`.
inline cloth::SceneParams flat_sheet(double height, double vz) {
  cloth::SceneParams p;
  p.grid = cloth::Grid{2, 2, 0.05};
  p.mass = 5e-4;
  p.stiffness = 50;
  p.damping = 0.1;
  p.pins = cloth::PinSet::none;
  p.initial_velocity_z = vz;
  p.origin = Eigen::Vector3d(0, 0, height);
  return p;
}

}  // namespace cloth_test
