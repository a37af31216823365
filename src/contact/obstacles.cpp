// Signed distances of the obstacles and the Coulomb correction of a step's end state.
#include "contact/obstacles.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cloth {

SurfacePoint surface_point(const Obstacle& obstacle, const Eigen::Vector3d& x) {
  if (const auto* plane = std::get_if<HalfSpace>(&obstacle))
    return {plane->normal.dot(x - plane->point), plane->normal};
  const auto& sphere = std::get<Sphere>(obstacle);
  const Eigen::Vector3d r = x - sphere.center;
  const double distance = r.norm();
  // At the centre every direction is as near to the surface as any other: take e_z.
  const Eigen::Vector3d n = distance > 0 ? Eigen::Vector3d(r / distance) : Eigen::Vector3d::UnitZ();
  return {distance - sphere.radius, n};
}

double clearance(const ContactModel& model, const Eigen::Vector3d& x) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Obstacle& obstacle : model.obstacles) {
    double phi = 0;
    if (const auto* plane = std::get_if<HalfSpace>(&obstacle)) {
      phi = plane->normal.dot(x - plane->point);
    } else {
      const auto& sphere = std::get<Sphere>(obstacle);
      phi = (x - sphere.center).norm() - sphere.radius;
    }
    nearest = std::min(nearest, phi - model.thickness);
  }
  return nearest;
}

void validate(const ContactModel& model) {
  if (!(std::isfinite(model.thickness) && model.thickness > 0))
    throw InputError("thickness = " + format_number(model.thickness) + ": expected a finite number > 0");
  if (!(model.skin > 0 && model.skin <= 1))
    throw InputError("skin = " + format_number(model.skin) + ": expected a fraction of the thickness in (0, 1]");
  const Friction& f = model.friction;
  if (!(std::isfinite(f.mu_s) && f.mu_s >= 0))
    throw InputError("mu_s = " + format_number(f.mu_s) + ": expected a finite number >= 0");
  if (!(std::isfinite(f.mu_k) && f.mu_k >= 0 && f.mu_k <= f.mu_s))
    throw InputError("mu_k = " + format_number(f.mu_k) + ": expected a finite number in [0, mu_s = " +
                     format_number(f.mu_s) + "]");
  for (const Obstacle& obstacle : model.obstacles) {
    if (const auto* plane = std::get_if<HalfSpace>(&obstacle)) {
      if (!(plane->point.allFinite() && plane->normal.allFinite() && std::abs(plane->normal.norm() - 1) < 1e-12))
        throw InputError("plane: expected a finite point and a unit normal");
    } else if (const auto& sphere = std::get<Sphere>(obstacle);
               !(sphere.center.allFinite() && std::isfinite(sphere.radius) && sphere.radius > 0)) {
      throw InputError("sphere radius = " + format_number(sphere.radius) +
                       ": expected a finite centre and a finite radius > 0");
    }
  }
}

namespace {
// [obstacle_contact]

// The cone applied to one impulse: a tangential vector t (a displacement or a velocity) that an impulse of normal
// size j_n acts on. Coulomb allows a tangential impulse up to mu_s j_n to hold t at zero; beyond it the contact
// slides and the tangential impulse is mu_k j_n, against t.
Eigen::Vector3d coulomb(const Eigen::Vector3d& t, double j_n, const Friction& friction) {
  const double t_norm = t.norm();
  if (t_norm <= friction.mu_s * j_n) return Eigen::Vector3d::Zero();  // inside the static cone: sticks
  return t * (1.0 - friction.mu_k * j_n / t_norm);                     // on the kinetic cone: slides
}

// What the displacement rule did to one particle against one obstacle.
enum class Touch { none, stuck, slid };

// The displacement rule for one particle against one obstacle: when x1 lies within the thickness (d > 0), moves it
// out along the normal n by d, passes its tangential displacement from x0 through the cone and sets n. Returns
// stuck when friction held the particle where it was along the surface.
Touch correct_displacement(const ContactModel& model, const Obstacle& obstacle, const Eigen::Vector3d& x0,
                           Eigen::Ref<Eigen::Vector3d> x1, Eigen::Vector3d& n) {
  const SurfacePoint surface = surface_point(obstacle, x1);
  const double d = model.thickness - surface.phi;  // penetration of the shell of the cloth's thickness
  if (!(d > 0)) return Touch::none;
  n = surface.normal;
  // Out along n by d; the tangential part through the cone, with the normal correction d as the impulse.
  const Eigen::Vector3d dx = x1 - x0 + d * n;
  const double dx_n = dx.dot(n);
  const Eigen::Vector3d t = coulomb(dx - dx_n * n, d, model.friction);
  x1 = x0 + dx_n * n + t;
  return model.friction.mu_s > 0 && t.isZero(0) ? Touch::stuck : Touch::slid;
}

// Particle s of (x1, v1) against every obstacle, the displacement measured from x0: the contacts corrected.
int resolve_particle(const ContactModel& model, Eigen::Index s, const Eigen::Ref<const Eigen::VectorXd>& x0,
                     Eigen::Ref<Eigen::VectorXd>& x1, Eigen::Ref<Eigen::VectorXd>& v1) {
  int contacts = 0;
  Eigen::Vector3d n;
  for (const Obstacle& obstacle : model.obstacles) {
    const Touch touch = correct_displacement(model, obstacle, x0.segment<3>(3 * s), x1.segment<3>(3 * s), n);
    if (touch == Touch::none) continue;
    ++contacts;
    const Eigen::Vector3d v = v1.segment<3>(3 * s);
    const double v_n = v.dot(n);
    if (touch == Touch::stuck) {
      // Held in place along the surface: no tangential velocity either, whatever the step's own velocity says.
      // A step whose displacement is not h v1 (a Runge-Kutta method's weighted stages) can otherwise end with a
      // velocity the particle never moves with, which its next step's stages then start from.
      v1.segment<3>(3 * s) = std::max(v_n, 0.0) * n;
    } else if (v_n < 0) {
      // The velocity: an inward normal part stopped, its tangential part through the cone with that impulse.
      v1.segment<3>(3 * s) = coulomb(v - v_n * n, -v_n, model.friction);
    }
  }
  return contacts;
}

// [obstacle_contact]
}  // namespace

int resolve_obstacle_contacts(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x0,
                              Eigen::Ref<Eigen::VectorXd> x1, Eigen::Ref<Eigen::VectorXd> v1) {
  int contacts = 0;
  for (Eigen::Index s = 0; s < x1.size() / 3; ++s) contacts += resolve_particle(model, s, x0, x1, v1);
  return contacts;
}

int resolve_obstacle_contacts(const ContactModel& model, const std::vector<int>& particles,
                              const Eigen::Ref<const Eigen::VectorXd>& x0, Eigen::Ref<Eigen::VectorXd> x1,
                              Eigen::Ref<Eigen::VectorXd> v1) {
  int contacts = 0;
  for (const int s : particles) contacts += resolve_particle(model, s, x0, x1, v1);
  return contacts;
}

int resolve_obstacle_contacts(const ContactModel& model, Eigen::Index s, const Eigen::Ref<const Eigen::VectorXd>& x0,
                              Eigen::Ref<Eigen::VectorXd>& x1, Eigen::Ref<Eigen::VectorXd>& v1) {
  return resolve_particle(model, s, x0, x1, v1);
}

int project_obstacle_contacts(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x0,
                              Eigen::Ref<Eigen::VectorXd> x1) {
  int contacts = 0;
  Eigen::Vector3d n;
  for (Eigen::Index s = 0; s < x1.size() / 3; ++s)
    for (const Obstacle& obstacle : model.obstacles)
      contacts += correct_displacement(model, obstacle, x0.segment<3>(3 * s), x1.segment<3>(3 * s), n) != Touch::none ? 1 : 0;
  return contacts;
}

double deepest_penetration(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x) {
  double deepest = -std::numeric_limits<double>::infinity();
  for (Eigen::Index s = 0; s < x.size() / 3; ++s)
    for (const Obstacle& obstacle : model.obstacles)
      deepest = std::max(deepest, model.thickness - surface_point(obstacle, x.segment<3>(3 * s)).phi);
  return deepest;
}

}  // namespace cloth
