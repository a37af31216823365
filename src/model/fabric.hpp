// A square of real fabric as a mass-spring scene (Chapter 10): the particle mass, the spring stiffnesses and the
// damping of a grid that resolves the same square with any number of particles, derived from the fabric's
// measured areal density, tensile stiffness and bending rigidity.
#pragma once

#include "model/scene.hpp"

namespace cloth {

/// What is measured on a fabric (Kawabata 1980's KES-F instruments measure the last two; a balance the first).
struct FabricMeasurements {
  double areal_density = 0.25;     ///< rho_A [kg/m^2]: 100 to 250 g/m^2 for shirting and sheeting, more for denim
  double tensile_stiffness = 2e4;  ///< C [N/m]: tension per unit width per unit strain, along warp or weft
  double bending_rigidity = 5e-6;  ///< B [N m]: bending moment per unit width per unit curvature
  double damping = 0.01;           ///< D [N s/m] per spring: a choice, not a measurement (see Chapter 10)
};

/// How the measurements become a grid's parameters.
struct FabricGrid {
  double side = 0.95;                 ///< length of the square's side [m] (20 particles at 0.05 m)
  int particles_per_side = 20;        ///< n: the grid is n x n, spacing d = side / (n - 1)
  double reference_curvature = 20.0;  ///< kappa_ref [1/m]: the flexion springs match B at this curvature
};

/// Mass of a particle that owns a d x d patch of fabric: m = rho_A d^2.
[[nodiscard]] double particle_mass(double areal_density, double spacing);

/// Stiffness of the structural and shear springs giving the sheet the tensile stiffness C along a grid line:
/// a uniform strain e along x stretches the structural x springs by e d, the shear springs by e d / sqrt 2 and the
/// flexion x springs by 2 e d, so per unit width C = k_structural + k_shear + 4 k_flexion, whatever d is.
[[nodiscard]] double stretch_spring_stiffness(double tensile_stiffness, double flexion_stiffness);

/// Stiffness of a flexion spring matching the bending energy B kappa^2 / 2 of its d x d patch at curvature kappa:
/// bent by the angle theta = kappa d, the spring's chord shortens by d theta^2 / 4 to leading order, so its energy
/// k d^2 theta^4 / 32 equals B theta^2 / 2 when k = 16 B / (kappa d^2)^2. It is quartic in the angle where
/// bending energy is quadratic: a flexion spring matches bending at one curvature only.
[[nodiscard]] double flexion_spring_stiffness(double bending_rigidity, double spacing, double curvature);

/// The scene: the square hanging from its four corners, released from rest, with the parameters above.
[[nodiscard]] SceneParams fabric_scene(const FabricMeasurements& fabric, const FabricGrid& grid);

}  // namespace cloth
