// The fastest angular frequency of an unbounded, flat mass-spring sheet at rest (Chapter 10's cost model): the
// explicit methods' stable step follows from it without building the cloth, and it says how that step scales
// with the spacing, the mass and the stiffness.
#pragma once

namespace cloth {

/// Spring stiffnesses of the three families [N/m] and the particle mass [kg] of a square lattice.
struct LatticeSprings {
  double structural = 0, shear = 0, flexion = 0;
  double mass = 1;
};

/// omega_max of the infinite lattice at rest: a plane wave exp(i q . r) of in-plane displacement has the squared
/// frequencies of the 2 x 2 dynamical matrix (1/m) sum over bonds r of 2 k (1 - cos q . r) u u^T (one bond per
/// direction of each family; at rest the out-of-plane displacements cost nothing to first order), and omega_max
/// is its largest value over the wave vectors q in [0, pi/d]^2, found on a fine grid and refined. The spacing
/// drops out of q . r. Examples: one K for all families gives omega_max^2 = 10.125 K / m, and flexion springs
/// much softer than the others give 8 K / m.
[[nodiscard]] double lattice_fastest_frequency(const LatticeSprings& springs);

}  // namespace cloth
