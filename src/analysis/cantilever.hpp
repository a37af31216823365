// The cantilever test of textile laboratories (Peirce 1930; ASTM D1388) as a scene (Chapter 12): a strip clamped
// level at one end, bent by its own weight, and its rest shape found by Newton's method on its total energy.
#pragma once

#include "model/bending.hpp"
#include "model/force_field.hpp"

#include <atomic>
#include <memory>
#include <vector>

namespace cloth {

/// The strip: what the standard and the fabric fix, and how the sheet is modeled.
struct CantileverParams {
  double overhang = 0.1;             ///< L [m]: from the clamp line to the tip
  double width = 0.025;              ///< W [m]: the standard's 2.5 cm (rounded to a whole number of spacings)
  double spacing = 0.005;            ///< d [m]
  double areal_density = 0.2;        ///< rho_A [kg/m^2]
  double bending_rigidity = 2.5e-6;  ///< B [N m]: bending moment per unit width per unit curvature
  double stiffness = 1e4;            ///< K [N/m] of the structural and shear springs (the sheet's stretching)
  BendingModel model = BendingModel::hinge;
  GridSplit split = GridSplit::both;     ///< how the cells are cut into triangles (model/bending.hpp)
  double reference_curvature = 20;   ///< kappa_ref [1/m]: where the flexion springs match B (model/fabric.hpp)
  double gravity = 9.81;             ///< g [m/s^2]
};

/// The grid the strip takes: L / d + 2 particles along it (the first two rows are the clamp, which fixes the
/// slope there), W / d + 1 across. Throws InputError when L or W is not close to a whole number of spacings
/// (within 1e-6 of one) or the strip has fewer than 2 cells along it.
Grid cantilever_grid(const CantileverParams& p);

/// The scene of the strip: the clamped rows pinned, structural and shear springs of stiffness K, plus flexion
/// springs of the stiffness that matches B at kappa_ref for the flexion model. Its gravity is 0: the weight is
/// applied by Cantilever with each particle's share of the strip's area.
SceneParams cantilever_scene(const CantileverParams& p);

/// Where the strip came to rest, and how close to rest it is.
struct CantileverRest {
  Vector x;                   ///< free positions
  int iterations = 0;         ///< Newton iterations
  double residual = 0;        ///< |f|_inf [N]: the largest force left on a particle
  double weight = 0;          ///< the weight of an interior particle, rho_A d^2 g [N], the scale of the residual
  bool converged = false;     ///< residual <= tolerance times weight
  bool interrupted = false;   ///< the stop flag ended the search
  double tip_deflection = 0;  ///< how far the tip row is below the clamp, averaged across the strip [m]
  double tip_x = 0;           ///< the tip row's distance from the clamp line along the strip's length [m]
  double chord_angle = 0;     ///< the tip chord below the horizontal [rad]
};

/// Where the rest-shape iteration starts.
enum class CantileverStart {
  flat,     ///< the strip as it lies on the platform: large rotations make Newton's steps short (80 and more)
  elastica  ///< each row laid along the heavy elastica of the strip's lambda at its arc length: unstretched, and
            ///< close to the discrete rest shape, so that Newton's method converges in a few steps. The start only
            ///< speeds the search: the rest shape found is the discrete one, to the tolerance.
};

/// The strip's energy (springs, bending, gravity), forces and rest shape.
class Cantilever {
 public:
  explicit Cantilever(const CantileverParams& params);

  [[nodiscard]] const CantileverParams& params() const { return params_; }
  [[nodiscard]] const Scene& scene() const { return *scene_; }
  /// Each free particle's mass: rho_A times its share of the strip's rectangle (d^2 inside, half on an edge, a
  /// quarter at a corner), so that the strip's weight per length is rho_A g W exactly.
  [[nodiscard]] const Vector& particle_masses() const { return masses_; }

  /// The total potential energy [J] at free positions x.
  double energy(const ConstVectorRef& x);
  /// The total force on every free particle.
  void forces(const ConstVectorRef& x, VectorRef f);

  /// The rest shape by Newton's method regularised by M / tau^2 with step halving (tau doubling while the energy falls, shrinking
  /// when it would rise or the matrix is not positive definite), from the flat strip. Converged when the largest
  /// force is at most `tolerance` times an interior particle's weight, or at the rounding level of the springs'
  /// forces, 64 eps K 2d.
  /// `stop`, when given, is read before each iteration: a value other than 0 ends the search there, with
  /// `interrupted` set and the shape reached so far.
  CantileverRest rest_shape(CantileverStart start = CantileverStart::elastica, double tolerance = 1e-9,
                            int max_iterations = 300, const std::atomic<int>* stop = nullptr);

  /// lambda = rho_A g L^3 / B = (L / c)^3, the heavy elastica's one parameter.
  [[nodiscard]] double lambda() const;
  /// The free positions of CantileverStart::elastica.
  [[nodiscard]] Vector elastica_layout() const;

  /// The tip measurements of a shape (the tip row averaged across the strip).
  void measure_tip(CantileverRest& rest) const;

 private:
  CantileverParams params_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<ForceField> field_;  // springs and the bending term of the strip's model
  Vector masses_, zero_velocity_, scratch_;
};

}  // namespace cloth
