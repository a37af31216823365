// Contact with fixed obstacles (Chapter 11): the ground, an inclined plane and a sphere, each an analytic signed
// distance, a cloth thickness, and Coulomb friction, applied as a correction of a step's end state that any
// integrator can take.
#pragma once

#include <Eigen/Core>
#include <variant>
#include <vector>

namespace cloth {

/// The solid side of the plane n . (x - p) = 0: phi(x) = n . (x - p), negative inside. The ground is the plane
/// through (0, 0, ground_z) with n = e_z; an incline at angle theta has n = (sin theta, 0, cos theta).
struct HalfSpace {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit outward normal
};

/// A solid ball: phi(x) = |x - c| - r, with outward normal (x - c) / |x - c|.
struct Sphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.3;
};

using Obstacle = std::variant<HalfSpace, Sphere>;

/// The signed distance phi of x from an obstacle's surface (negative inside) and its outward unit normal there.
struct SurfacePoint {
  double phi;
  Eigen::Vector3d normal;
};
[[nodiscard]] SurfacePoint surface_point(const Obstacle& obstacle, const Eigen::Vector3d& x);

/// Coulomb's coefficients: a contact sticks while its tangential force lies inside the cone |f_t| <= mu_s f_n,
/// and slides with |f_t| = mu_k f_n otherwise.
struct Friction {
  double mu_s = 0.0;  ///< static coefficient
  double mu_k = 0.0;  ///< kinetic coefficient, at most mu_s
};

/// The obstacles of a scene and how the cloth touches them. A particle is in contact when its centre is closer
/// than `thickness` to an obstacle's surface (phi < thickness): the cloth is a shell of that thickness.
struct ContactModel {
  std::vector<Obstacle> obstacles;
  double thickness = 0.005;  ///< [m]
  Friction friction;
  /// Whether the cloth also collides with itself (contact/self_collision.hpp), with the same thickness.
  bool self_collision = false;
  /// Self-collision's skin, a fraction of the thickness (SelfCollision).
  double skin = 0.25;
};

/// Throws InputError naming the first parameter out of range (thickness > 0, skin in (0, 1], 0 <= mu_k <= mu_s,
/// unit normals, radius > 0, everything finite).
void validate(const ContactModel& model);

/// Corrects the end (x1, v1) of a step that started at x0 for contact with the obstacles, particle by particle
/// (3 coordinates per particle), and returns the number of particle-obstacle contacts it corrected. For each
/// particle with phi(x1) < thickness, with d = thickness - phi the penetration and n the normal:
///  - the displacement x1 - x0: moved out along n by d, and its tangential part reduced by the cone: removed
///    when it is at most mu_s d (sticking), else shortened by mu_k d (sliding);
///  - the velocity, when it points into the obstacle (v_n < 0): v_n set to 0 (a perfectly inelastic contact),
///    and its tangential part removed when at most mu_s |v_n|, else shortened by mu_k |v_n|; when the
///    displacement stuck (with friction), the tangential velocity is removed too, so that a particle held in
///    place does not keep a velocity it does not move with.
/// Both rules are the cone applied to an impulse: the one that corrects the displacement and the one that
/// stops the normal velocity. Velocities leaving the obstacle are not touched, and without friction the
/// tangential motion is not either.
int resolve_obstacle_contacts(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x0,
                              Eigen::Ref<Eigen::VectorXd> x1, Eigen::Ref<Eigen::VectorXd> v1);
/// The same for the listed particles only: after a pass of the self-contact response, the particles it moved (the
/// others are where the last correction left them).
int resolve_obstacle_contacts(const ContactModel& model, const std::vector<int>& particles,
                              const Eigen::Ref<const Eigen::VectorXd>& x0, Eigen::Ref<Eigen::VectorXd> x1,
                              Eigen::Ref<Eigen::VectorXd> v1);

/// How far x lies outside every obstacle's shell: the smallest phi(x) - thickness over the obstacles. Where it is
/// positive the correction leaves the particle alone, and since a signed distance changes no faster than the point
/// moves (|phi(y) - phi(x)| <= |y - x|), so does it at any point y closer to x than that.
[[nodiscard]] double clearance(const ContactModel& model, const Eigen::Vector3d& x);

/// The same for particle s alone (a sweep that does more to each particle calls it with the views it holds).
int resolve_obstacle_contacts(const ContactModel& model, Eigen::Index s, const Eigen::Ref<const Eigen::VectorXd>& x0,
                              Eigen::Ref<Eigen::VectorXd>& x1, Eigen::Ref<Eigen::VectorXd>& v1);

/// The displacement rule of resolve_obstacle_contacts alone, for methods whose velocities follow from their
/// positions (XPBD: v = (x1 - x0) / h): the contacts as inequality constraints phi(x) >= thickness, projected,
/// with the cone applied to the displacement (Macklin et al. 2014's position-level friction).
int project_obstacle_contacts(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x0,
                              Eigen::Ref<Eigen::VectorXd> x1);

/// The deepest penetration, max over particles and obstacles of thickness - phi (negative when nothing touches).
[[nodiscard]] double deepest_penetration(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x);

}  // namespace cloth
