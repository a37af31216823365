// Fabric measurements to grid parameters (the derivations are in fabric.hpp and on the Chapter 10 page).
#include "model/fabric.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"

#include <cmath>
#include <string>

namespace cloth {

double particle_mass(double areal_density, double spacing) { return areal_density * spacing * spacing; }

double stretch_spring_stiffness(double tensile_stiffness, double flexion_stiffness) {
  return (tensile_stiffness - 4 * flexion_stiffness) / 2;
}

double flexion_spring_stiffness(double bending_rigidity, double spacing, double curvature) {
  const double kappa_d2 = curvature * spacing * spacing;
  return 16 * bending_rigidity / (kappa_d2 * kappa_d2);
}

SceneParams fabric_scene(const FabricMeasurements& fabric, const FabricGrid& grid) {
  if (grid.particles_per_side < 3)
    throw InputError("fabric grid: " + std::to_string(grid.particles_per_side) +
                     " particles per side: expected at least 3 (flexion springs span two spacings)");
  if (!(grid.side > 0 && grid.reference_curvature > 0 && fabric.areal_density > 0 && fabric.tensile_stiffness > 0 &&
        fabric.bending_rigidity > 0 && fabric.damping >= 0))
    throw InputError("fabric: side, curvature, density, tensile stiffness and bending rigidity must be > 0, "
                     "damping >= 0");
  SceneParams p;
  const double d = grid.side / (grid.particles_per_side - 1);
  p.grid = Grid{grid.particles_per_side, grid.particles_per_side, d};
  p.mass = particle_mass(fabric.areal_density, d);
  const double k_flexion = flexion_spring_stiffness(fabric.bending_rigidity, d, grid.reference_curvature);
  p.stiffness = stretch_spring_stiffness(fabric.tensile_stiffness, k_flexion);
  if (!(p.stiffness > 0))
    throw InputError("fabric: the flexion springs alone (k = " + format_number(k_flexion) +
                     " N/m) are stiffer in tension than the fabric (C = " + format_number(fabric.tensile_stiffness) +
                     " N/m): expected B / (kappa d)^2 < C / 64");
  p.flexion_stiffness = k_flexion;
  p.damping = fabric.damping;
  p.pins = PinSet::corners;
  p.initial_velocity_z = 0;
  return p;
}

}  // namespace cloth
