// Building a scene: pinned set, free-slot numbering, springs and the initial state.
#include "model/scene.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"

#include <Eigen/LU>  // determinant() of the placement
#include <algorithm>
#include <cmath>
#include <string>

namespace cloth {

const char* damping_model_name(DampingModel model) {
  return model == DampingModel::projected ? "projected" : "report";
}

const char* pin_set_name(PinSet pins) {
  switch (pins) {
    case PinSet::corners: return "corners";
    case PinSet::corner: return "corner";
    case PinSet::edge: return "edge";
    case PinSet::none: return "none";
    case PinSet::clamped: return "clamped";
  }
  return "?";
}

namespace {

bool pinned(const Grid& g, PinSet pins, int i, int j) {
  switch (pins) {
    case PinSet::corners: return (i == 0 || i == g.M - 1) && (j == 0 || j == g.N - 1);
    case PinSet::corner: return i == 0 && j == 0;
    case PinSet::edge: return j == g.N - 1;
    case PinSet::none: return false;
    case PinSet::clamped: return i <= 1;
  }
  return false;
}

}  // namespace

void validate(const SceneParams& p) {
  const Grid& g = p.grid;
  if (g.M < 2 || g.N < 2)
    throw InputError("grid " + std::to_string(g.M) + "x" + std::to_string(g.N) +
                     " is too small: a cloth needs at least 2 particles in each direction (MxN with M, N >= 2)");
  if (static_cast<long long>(g.M) * g.N > max_particles)
    throw InputError("grid " + std::to_string(g.M) + "x" + std::to_string(g.N) + " has more than " +
                     std::to_string(max_particles) + " particles, the largest this program accepts");
  if (!(std::isfinite(g.d) && g.d > 0))
    throw InputError("spacing " + format_number(g.d) + ": expected a finite number > 0");
  if (!(std::isfinite(p.stiffness) && p.stiffness > 0))
    throw InputError("stiffness K = " + format_number(p.stiffness) + ": expected a finite number > 0");
  if (p.flexion_stiffness && !(std::isfinite(*p.flexion_stiffness) && *p.flexion_stiffness > 0))
    throw InputError("flexion stiffness = " + format_number(*p.flexion_stiffness) + ": expected a finite number > 0");
  if (!(std::isfinite(p.damping) && p.damping >= 0))
    throw InputError("damping D = " + format_number(p.damping) + ": expected a finite number >= 0");
  if (!std::isfinite(p.initial_velocity_z))
    throw InputError("v0 = " + format_number(p.initial_velocity_z) + ": expected a finite number");
  if (!std::isfinite(p.initial_swing))
    throw InputError("swing = " + format_number(p.initial_swing) + ": expected a finite number");
  if (p.bending != BendingModel::flexion && !(std::isfinite(p.bending_rigidity) && p.bending_rigidity > 0))
    throw InputError("bending rigidity B = " + format_number(p.bending_rigidity) + ": expected a finite number > 0");
  if (!(std::isfinite(p.mass) && p.mass > 0))
    throw InputError("mass = " + format_number(p.mass) + ": expected a finite number > 0");
  if (!(std::isfinite(p.gravity) && p.gravity >= 0))
    throw InputError("gravity = " + format_number(p.gravity) + ": expected a finite number >= 0");
  if (!(p.families.on[0] || p.families.on[1] || p.families.on[2]))
    throw InputError("springs: at least one family of structural, shear, flexion is needed");
  const Eigen::Matrix3d& R = p.orientation;
  if (!(R.allFinite() && p.origin.allFinite() &&
        (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-12 && R.determinant() > 0))
    throw InputError("placement: expected a finite origin and a rotation (R^T R = I, det R = 1) as orientation");
  int free = 0;
  for (int i = 0; i < g.M; ++i)
    for (int j = 0; j < g.N; ++j) free += pinned(g, p.pins, i, j) ? 0 : 1;
  if (free == 0)
    throw InputError("pins " + std::string(pin_set_name(p.pins)) + " on a " + std::to_string(g.M) + "x" +
                     std::to_string(g.N) + " grid leave no free particle to simulate");
}

Scene::Scene(const SceneParams& params) : params_(params) {
  validate(params_);
  const Grid& g = params_.grid;
  const int n = g.particle_count();
  slot_of_particle_.assign(static_cast<std::size_t>(n), -1);
  particle_of_slot_.reserve(static_cast<std::size_t>(n));
  // Free particles take the first slots, so the unknowns are one contiguous block of every per-slot array.
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < g.M; ++i)
      for (int j = 0; j < g.N; ++j)
        if (pinned(g, params_.pins, i, j) == (pass == 1)) {
          slot_of_particle_[static_cast<std::size_t>(g.particle(i, j))] = static_cast<int>(particle_of_slot_.size());
          particle_of_slot_.push_back(g.particle(i, j));
          if (pass == 0) ++free_count_;
        }

  springs_ = build_springs(g, params_.families, slot_of_particle_);
  stiffness_.fill(params_.stiffness);
  if (params_.flexion_stiffness) set_family_stiffness(SpringFamily::flexion, *params_.flexion_stiffness);
  damping_.fill(params_.damping);

  rest_positions_.resize(3 * n);
  for (int s = 0; s < n; ++s) {
    const int particle = particle_of_slot_[static_cast<std::size_t>(s)];
    rest_positions_.segment<3>(3 * s) =
        params_.origin + params_.orientation * g.rest_position(particle / g.N, particle % g.N);
  }
}

bool Scene::has_damping() const {
  // std::any_of on iterators rather than std::ranges::any_of: Emscripten 3.1's libc++ (the book's WebAssembly
  // build) has no ranges algorithms.
  return std::any_of(all_spring_families.begin(), all_spring_families.end(),
                     [this](SpringFamily f) { return damping(f) != 0.0 && springs_.count(f) > 0; });
}

Eigen::VectorXd Scene::initial_positions() const { return rest_positions_.head(dof_count()); }

Eigen::VectorXd Scene::initial_velocities() const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(dof_count());
  const Grid& g = params_.grid;
  for (int s = 0; s < free_count_; ++s) {
    // A rigid turn at rate w about the edge's line: v = w e_x x (r - r_edge), whose z part is w (y_edge - y).
    const int j = particle_of_slot_[static_cast<std::size_t>(s)] % g.N;
    v[3 * s + 2] = params_.initial_velocity_z + params_.initial_swing * (g.N - 1 - j) * g.d;
  }
  return v;
}

void Scene::all_positions(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> out) const {
  for (int s = 0; s < particle_count(); ++s) {
    const int particle = particle_of_slot_[static_cast<std::size_t>(s)];
    if (s < free_count_) out.segment<3>(3 * particle) = x.segment<3>(3 * s);
    else out.segment<3>(3 * particle) = rest_positions_.segment<3>(3 * s);
  }
}

}  // namespace cloth
