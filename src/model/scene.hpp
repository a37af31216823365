// A Scene says exactly what is modeled: the grid, which spring families and force terms exist, which particles
// are pinned, and how the cloth starts. Pinned particles are not unknowns: the state holds free particles only.
#pragma once

#include "model/grid.hpp"
#include "model/springs.hpp"

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cloth {

/// The damping law of a spring (docs/model.md).
enum class DampingModel {
  projected,  ///< f_p = -D ((v_p - v_q) . u) u: damps only the stretching rate (the book's default)
  report      ///< f_p = -D (v_p - v_q) |x_p - x_q|: the report's law with its sign corrected
};

/// Which particles keep their rest position with zero velocity.
enum class PinSet {
  corners,  ///< the four corners (the report's scene)
  corner,   ///< the one corner (0, 0)
  edge,     ///< the whole edge j = N-1
  none,     ///< nothing: the cloth falls freely
  clamped   ///< the first two rows i = 0 and 1: the clamp of Chapter 12's cantilever, which also fixes the slope
};

/// How a sheet resists bending (Chapter 12).
enum class BendingModel {
  flexion,   ///< the flexion springs alone (the report's model; Chapter 10 maps B to their stiffness at one curvature)
  hinge,     ///< E = (B/2) c theta^2 |e|^2 / A_e per interior edge: the dihedral angle theta (discrete shells)
  quadratic  ///< E = (B/2) c |sum_i w_i x_i|^2 / A_e per interior edge: constant Hessian (isometric bending)
};

/// How each grid cell is cut into triangles.
enum class GridSplit {
  uniform,  ///< every cell along its diagonal from (i, j) to (i+1, j+1)
  both      ///< both triangulations of the grid, each at half weight: the two diagonals' biases cancel
};

const char* damping_model_name(DampingModel model);
const char* pin_set_name(PinSet pins);

/// The report's scene and its variations: every number a Scene is built from.
struct SceneParams {
  Grid grid;
  double stiffness = 50.0;            ///< K [N/m], for every family unless flexion_stiffness says otherwise
  /// K of the flexion springs alone [N/m] (Chapter 10: fabric bends far more easily than it stretches); unset,
  /// the flexion springs take `stiffness` like the others.
  std::optional<double> flexion_stiffness;
  double damping = 0.0;               ///< D [N s/m] (projected) or [N s/m^2] (report law), for every family
  DampingModel damping_model = DampingModel::projected;
  FamilySet families = FamilySet::all();
  PinSet pins = PinSet::corners;
  double initial_velocity_z = -20.0;  ///< v0: z velocity of every free particle at t = 0 [m/s]
  /// w: the cloth starts turning rigidly about the line of the edge j = N-1 (y = (N-1) d, z = 0) at w rad/s, on top
  /// of v0; w > 0 lifts the far edge. Particle (i, j) gets the z velocity w (N-1-j) d (Chapter 10's swinging curtain).
  double initial_swing = 0.0;
  /// The bending term: hinge and quadratic add an energy on the triangles' interior edges with rigidity
  /// bending_rigidity to every force, energy and Jacobian of the ForceField; flexion adds nothing (the flexion
  /// springs, when `families` has them, are then the only resistance to bending).
  BendingModel bending = BendingModel::flexion;
  double bending_rigidity = 5e-6;     ///< B [N m], used by the hinge and quadratic models
  GridSplit bending_split = GridSplit::both;  ///< the triangles the hinge and quadratic energies live on
  double mass = 1.0;                  ///< m, the same for every particle [kg]
  double gravity = 9.81;              ///< g [m/s^2]; 0 removes the gravity term
  /// Where the grid rests (Chapter 11 lays a sheet on an inclined plane): particle (i, j) rests at
  /// origin + orientation (i d, j d, 0). Identity and zero, the report's placement; orientation must be a rotation.
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

/// The largest grid a scene accepts, checked before anything is allocated.
inline constexpr long long max_particles = 4'000'000;

/// Throws InputError (see base/input_error.hpp) naming the first parameter out of range.
void validate(const SceneParams& params);

/// A built scene. Particles are numbered in "slots": the free particles first, in grid order, then the pinned
/// ones. The unknowns x, v are the 3 n_free coordinates of the free slots, so slot s < n_free owns x[3s..3s+2].
class Scene {
 public:
  explicit Scene(const SceneParams& params);

  [[nodiscard]] const SceneParams& params() const { return params_; }
  [[nodiscard]] const Grid& grid() const { return params_.grid; }
  [[nodiscard]] const SpringSet& springs() const { return springs_; }

  [[nodiscard]] int particle_count() const { return params_.grid.particle_count(); }
  [[nodiscard]] int free_count() const { return free_count_; }
  [[nodiscard]] int dof_count() const { return 3 * free_count_; }
  [[nodiscard]] int slot(int particle) const { return slot_of_particle_[static_cast<std::size_t>(particle)]; }
  [[nodiscard]] int particle_of_slot(int slot) const { return particle_of_slot_[static_cast<std::size_t>(slot)]; }
  [[nodiscard]] bool is_pinned(int particle) const { return slot(particle) >= free_count_; }

  /// K and D of a family (the same for all families unless a chapter sets them apart).
  [[nodiscard]] double stiffness(SpringFamily f) const { return stiffness_[static_cast<int>(f)]; }
  [[nodiscard]] double damping(SpringFamily f) const { return damping_[static_cast<int>(f)]; }
  void set_family_stiffness(SpringFamily f, double K) { stiffness_[static_cast<int>(f)] = K; }
  void set_family_damping(SpringFamily f, double D) { damping_[static_cast<int>(f)] = D; }

  /// Whether a force term is modeled at all; a term that is not costs nothing in the force loops.
  [[nodiscard]] bool has_damping() const;
  [[nodiscard]] bool has_gravity() const { return params_.gravity != 0.0; }

  /// Rest positions of all slots (3 per slot, free slots first): the pinned tail never changes.
  [[nodiscard]] const Eigen::VectorXd& rest_positions() const { return rest_positions_; }
  /// Initial free-particle positions x(0) (the rest configuration) and velocities v(0) = (0, 0, v0 + w (N-1-j) d).
  [[nodiscard]] Eigen::VectorXd initial_positions() const;
  [[nodiscard]] Eigen::VectorXd initial_velocities() const;

  /// Positions of every particle in grid order (3 per particle), pinned ones at rest, from free positions x.
  void all_positions(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> out) const;

 private:
  SceneParams params_;
  std::vector<int> slot_of_particle_;
  std::vector<int> particle_of_slot_;
  int free_count_ = 0;
  SpringSet springs_;
  std::array<double, 3> stiffness_{};
  std::array<double, 3> damping_{};
  Eigen::VectorXd rest_positions_;
};

}  // namespace cloth
