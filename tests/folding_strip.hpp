// Chapter 11's folding strip at test size, shared by the fold and skin-per-particle tests: the scene and the contact
// model (the ground and self-collision) with which the strip falls and folds onto itself.
#pragma once

#include "contact/obstacles.hpp"
#include "model/fabric.hpp"

#include <Eigen/Geometry>
#include <numbers>

namespace cloth_test {

// 10 x 40 particles: 1 cm spacing, 0.2 kg/m^2, K = 20 N/m, D = 0.002 N s/m, standing on the ground 2 degrees off
// the vertical, from rest, its lowest row one thickness above the ground.
inline cloth::SceneParams standing_strip(double thickness) {
  cloth::SceneParams p;
  p.grid = cloth::Grid{10, 40, 0.01};
  p.mass = cloth::particle_mass(0.2, p.grid.d);
  p.stiffness = 20;
  p.damping = 0.002;
  p.pins = cloth::PinSet::none;
  p.initial_velocity_z = 0;
  p.orientation = Eigen::AngleAxisd(88 * std::numbers::pi / 180, Eigen::Vector3d::UnitX()).toRotationMatrix();
  p.origin = Eigen::Vector3d(0, 0, thickness);
  return p;
}

// The ground with Coulomb friction (mu_s = 0.3, mu_k = 0.2) and self-collision at the given thickness.
inline cloth::ContactModel ground_and_self(double thickness) {
  cloth::ContactModel model;
  model.obstacles.emplace_back(cloth::HalfSpace{});
  model.thickness = thickness;
  model.friction = {0.3, 0.2};
  model.self_collision = true;
  return model;
}

}  // namespace cloth_test
