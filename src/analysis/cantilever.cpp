// The cantilever strip: its grid, its weight by area, and its rest shape by regularised Newton steps.
#include "analysis/cantilever.hpp"

#include "analysis/elastica.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "model/fabric.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace cloth {

namespace {

// The whole number of spacings in `length`, or InputError naming `what`.
int spacings_in(double length, double d, const char* what) {
  const double ratio = length / d;
  const long long n = std::llround(ratio);
  if (!(std::abs(ratio - static_cast<double>(n)) <= 1e-6 * ratio) || n < 1 || n > 100000)
    throw InputError(std::string(what) + " " + format_number(length) + " m is " + format_number(ratio) +
                     " spacings of " + format_number(d) + " m: expected a whole number of spacings from 1 to 100000");
  return static_cast<int>(n);
}

}  // namespace

Grid cantilever_grid(const CantileverParams& p) {
  if (!(std::isfinite(p.spacing) && p.spacing > 0))
    throw InputError("spacing " + format_number(p.spacing) + ": expected a finite number > 0");
  const int along = spacings_in(p.overhang, p.spacing, "overhang");
  if (along < 2)
    throw InputError("overhang " + format_number(p.overhang) + " m: expected at least 2 spacings of " +
                     format_number(p.spacing) + " m");
  // The standard's width rounded to the nearest whole number of spacings (at least one cell).
  const int across = std::max(1, static_cast<int>(std::lround(p.width / p.spacing)));
  return Grid{along + 2, across + 1, p.spacing};
}

SceneParams cantilever_scene(const CantileverParams& p) {
  if (!(std::isfinite(p.areal_density) && p.areal_density > 0))
    throw InputError("areal density " + format_number(p.areal_density) + ": expected a finite number > 0");
  if (!(std::isfinite(p.bending_rigidity) && p.bending_rigidity > 0))
    throw InputError("bending rigidity " + format_number(p.bending_rigidity) + ": expected a finite number > 0");
  SceneParams s;
  s.grid = cantilever_grid(p);
  s.stiffness = p.stiffness;
  s.mass = particle_mass(p.areal_density, p.spacing);
  s.pins = PinSet::clamped;
  s.initial_velocity_z = 0;
  s.gravity = 0;
  s.damping = 0;
  if (p.model == BendingModel::flexion) {
    s.families = FamilySet::all();
    s.flexion_stiffness = flexion_spring_stiffness(p.bending_rigidity, p.spacing, p.reference_curvature);
  } else {
    s.families = FamilySet::all();
    s.families.on[static_cast<int>(SpringFamily::flexion)] = false;
    s.bending = p.model;
    s.bending_rigidity = p.bending_rigidity;
    s.bending_split = p.split;
  }
  return s;
}

Cantilever::Cantilever(const CantileverParams& params)
    : params_(params), scene_(std::make_unique<Scene>(cantilever_scene(params))) {
  field_ = std::make_unique<ForceField>(*scene_);
  const Grid& g = scene_->grid();
  masses_.resize(scene_->free_count());
  for (int s = 0; s < scene_->free_count(); ++s) {
    const int particle = scene_->particle_of_slot(s), i = particle / g.N, j = particle % g.N;
    const double along = i == g.M - 1 ? 0.5 : 1.0, across = (j == 0 || j == g.N - 1) ? 0.5 : 1.0;
    masses_[s] = params.areal_density * along * across * g.d * g.d;
  }
  zero_velocity_ = Vector::Zero(scene_->dof_count());
  scratch_.resize(scene_->dof_count());
}

double Cantilever::energy(const ConstVectorRef& x) {
  double gravity = 0;
  for (int s = 0; s < scene_->free_count(); ++s) gravity += masses_[s] * params_.gravity * x[3 * s + 2];
  return field_->energy(x, zero_velocity_).spring + gravity;  // springs and bending
}

void Cantilever::forces(const ConstVectorRef& x, VectorRef f) {
  field_->forces(x, zero_velocity_, f);  // springs and bending
  for (int s = 0; s < scene_->free_count(); ++s) f[3 * s + 2] -= masses_[s] * params_.gravity;
}

void Cantilever::measure_tip(CantileverRest& rest) const {
  const Grid& g = scene_->grid();
  double x = 0, z = 0;
  for (int j = 0; j < g.N; ++j) {
    const int s = scene_->slot(g.particle(g.M - 1, j));
    x += rest.x[3 * s] / g.N;
    z += rest.x[3 * s + 2] / g.N;
  }
  rest.tip_x = x - g.d;  // the clamp line is row i = 1, at x = d
  rest.tip_deflection = -z;
  rest.chord_angle = std::atan2(rest.tip_deflection, rest.tip_x);
}

double Cantilever::lambda() const {
  return params_.areal_density * params_.gravity * std::pow(params_.overhang, 3) / params_.bending_rigidity;
}

Vector Cantilever::elastica_layout() const {
  const Grid& g = scene_->grid();
  const int cells = g.M - 2, per_cell = 40;
  const ElasticaShape shape = heavy_elastica(lambda(), cells * per_cell);
  Vector x = scene_->initial_positions();
  for (int s = 0; s < scene_->free_count(); ++s) {
    const int i = scene_->particle_of_slot(s) / g.N;
    const auto k = static_cast<std::size_t>((i - 1) * per_cell);  // arc length (i - 1) d from the clamp line
    x[3 * s] = g.d + params_.overhang * shape.x[k];
    x[3 * s + 2] = -params_.overhang * shape.y[k];
  }
  return x;
}

CantileverRest Cantilever::rest_shape(CantileverStart start, double tolerance, int max_iterations,
                                      const std::atomic<int>* stop) {
  const int n = scene_->dof_count();
  CantileverRest rest;
  rest.x = start == CantileverStart::elastica ? elastica_layout() : scene_->initial_positions();
  rest.weight = params_.areal_density * params_.spacing * params_.spacing * params_.gravity;
  // One pattern for every matrix of the search (springs and hinges, ForceField::pattern()), analysed once:
  // each iteration refills values in place.
  SparseMatrix A = field_->pattern(), dfdv = field_->pattern();
  std::vector<int> diagonal(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) diagonal[static_cast<std::size_t>(k)] = static_cast<int>(&A.coeffRef(k, k) - A.valuePtr());
  Vector f(n), f_trial(n), x_trial(n), dx(n), mass_diagonal(n);
  for (int k = 0; k < n; ++k) mass_diagonal[k] = masses_[k / 3];
  Eigen::SimplicialLDLT<SparseMatrix> solver;
  solver.analyzePattern(A);
  double E = energy(rest.x);
  forces(rest.x, f);
  // The force rounding leaves: a coordinate of size X = L + W is stored to eps X, so a spring's force to K eps X,
  // and a particle sums eight of them. A fine or light strip's weight may be below it (3e-7 weights at L/160 of
  // the book's test strip, where the search stalls at 3.1e-13 N).
  const double floor = 8 * std::numeric_limits<double>::epsilon() * params_.stiffness *
                       (params_.overhang + params_.width);
  const double target = std::max(tolerance * rest.weight, floor);
  double tau = 1e-2;  // [s]: the first steps may be short pseudo-time steps, later ones are Newton's
  for (; rest.iterations < max_iterations; ++rest.iterations) {
    rest.residual = f.lpNorm<Eigen::Infinity>();
    if (rest.residual <= target) break;
    if (stop != nullptr && stop->load() != 0) {
      rest.interrupted = true;
      break;
    }
    // [newton_step]
    // Hessian of the energy, -df/dx (springs and bending), plus M / tau^2.
    field_->jacobians(rest.x, zero_velocity_, A, dfdv);
    A.coeffs() *= -1;
    for (int k = 0; k < n; ++k) A.valuePtr()[diagonal[static_cast<std::size_t>(k)]] += mass_diagonal[k] / (tau * tau);
    solver.factorize(A);
    bool definite = solver.info() == Eigen::Success && solver.vectorD().minCoeff() > 0;
    if (!definite) {
      // Compressed springs (the inside of a bend of flexion springs) and hinges folded past their inflection make
      // the exact Hessian indefinite: their definite parts (the axial term alone for compressed springs, after
      // Choi & Ko 2002; Gauss-Newton for the hinges) give a descent direction instead. newton_matrix is
      // M - tau^2 df/dx with the scene's uniform masses.
      field_->newton_matrix(rest.x, zero_velocity_, tau, StiffnessTreatment::definite, A);
      A.coeffs() /= tau * tau;
      solver.factorize(A);
      definite = solver.info() == Eigen::Success && solver.vectorD().minCoeff() > 0;
    }
    // The step, then its halves while the energy rises: the full step of a strip far from its rest shape
    // overshoots, and a shorter one along the same direction usually does not.
    bool accepted = false;
    double alpha = 1;
    if (definite) {
      dx = solver.solve(f);
      for (int halving = 0; halving < 6 && !accepted; ++halving) {
        if (halving > 0) alpha /= 2;
        x_trial = rest.x + alpha * dx;
        const double E_trial = energy(x_trial);
        forces(x_trial, f_trial);
        // Near the minimum the energy's change is below its rounding: a step that lowers the force is taken.
        const double rounding = 64 * std::numeric_limits<double>::epsilon() * (std::abs(E) + std::abs(E_trial));
        accepted = E_trial < E || (E_trial <= E + rounding && f_trial.lpNorm<Eigen::Infinity>() < rest.residual);
        if (accepted) {
          rest.x = x_trial;
          f = f_trial;
          E = E_trial;
        }
      }
    }
    tau = accepted && alpha == 1 ? std::min(2 * tau, 1e6) : accepted ? tau : tau / 4;
    // [newton_step]
    if (tau < 1e-12) break;
  }
  rest.residual = f.lpNorm<Eigen::Infinity>();
  rest.converged = rest.residual <= target;
  measure_tip(rest);
  return rest;
}

}  // namespace cloth
