// The constrained cloth of Chapter 10: fast projection (Goldenthal et al. 2007) and RATTLE (Andersen 1983) with the
// structural springs held at their rest lengths and the shear springs as compliant constraints.
//
// The constraints. C_j(x) = |x_p - x_q| - L0_j, with gradient u_j = (x_p - x_q) / |x_p - x_q| at p and -u_j at q,
// so J M^-1 J^T has the diagonal w_p + w_q (w the inverse masses, 0 for a pinned particle) and, for two
// constraints a, b sharing the free particle s, the entry w_s (sign_a u_a) . (sign_b u_b). Its pattern is fixed
// by the grid: it is built, and its fill-reducing ordering and symbolic factorization computed, once.
//
// Which springs. At K = 1e5 N/m a spring's stretch under the cloth's load is micrometres (Chapter 10 derives it),
// so holding the structural springs at their rest length costs nothing in accuracy and removes the stiff stretch
// waves from the step. The shear springs are as stiff here, but they cannot be held too: a flat sheet has two
// in-plane freedoms a particle, and structural springs with even one diagonal per square are more constraints
// than that, so at the flat start J M^-1 J^T would be singular and near it the projection would not converge.
// Given their own compliance alpha = 1/K, the shear springs' equations C = alpha~ Lambda are solvable
// everywhere and the matrix J M^-1 J^T + diag(alpha~) is definite (every self-stress of the grid uses a diagonal),
// which is XPBD's form of a spring (Macklin et al. 2016) solved by Newton's method instead of Gauss-Seidel. The
// flexion springs stay forces: their lengths change at second order in a fold, which is how the sheet bends.
//
// The projection. x = x~ - M^-1 J^T Lambda must satisfy C_j(x) + alpha~_j Lambda_j = 0 (alpha~ = 0 for a hard
// constraint). Each iteration linearises C at the current iterate x_k: solve (J M^-1 J^T + diag alpha~) dLambda =
// C(x_k) + alpha~ Lambda_k, x_{k+1} = x_k - M^-1 J(x_k)^T dLambda: Goldenthal et al.'s fast projection with the
// compliant rows added; the matrix is refactorized at every iterate (numerically only).
//
// Fast projection (Goldenthal et al. 2007, Algorithm 1): x~ = x_n + h (v_n + h M^-1 f(x_n, v_n)), projected with
// alpha~ = alpha / h^2 (implicit Euler's spring), v = (x_{n+1} - x_n) / h. First order; like implicit Euler it
// shortens every rotation a little each step.
//
// RATTLE (Andersen 1983), the velocity Verlet of constrained mechanics:
//   x~ = x_n + h v_n + h^2/2 M^-1 f(x_n, v_n),  x_{n+1} = x~ - M^-1 J^T Lambda,  C(x_{n+1}) + alpha~ Lambda = 0,
//   v* = (x_{n+1} - x_n) / h + h/2 M^-1 (f(x_{n+1}, .) + f_shear(x_{n+1})),
//   v_{n+1} = v* - M^-1 J_s^T mu with J_s(x_{n+1}) v_{n+1} = 0 for the structural constraints.
// Here alpha~ = 2 alpha / h^2 (Lambda is h^2/2 times the shear force). The multipliers act along SHAKE's
// J(x_n) (Ryckaert, Ciccotti and Berendsen 1977), solved by a simplified Newton method with the matrix
// J(x_n) M^-1 J(x_n)^T + diag(alpha~) factorized once per step; it contracts by about the angle a constraint turns
// in a step. Along the iterates' own gradients instead (as fast projection does) the positions would change by
// O(h^3) a step, and the velocity (x_{n+1} - x_n) / h by O(h^2): first order. The shear springs' force enters both half kicks at x_{n+1}, which
// is first order in how fast that force changes; near its quasi-static value (the stiff shear modes are not
// excited) that change is as slow as the motion and its error small. The dampers take the velocities of the
// moment: explicit, as in symplectic Euler (D h / m is 0.06 at the steps used here).
#include "integrators/fast_projection.hpp"

#include "base/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace cloth {

ConstrainedCloth::ConstrainedCloth(ForceField& field, std::string name, ConstrainedScheme scheme, double tolerance,
                                   int max_iterations)
    : Stepper(field), name_(std::move(name)), scheme_(scheme), tolerance_(tolerance), max_iterations_(max_iterations) {
  const Scene& scene = field.scene();
  // Held at their rest lengths, the edges of a sheet hung by its corners are straight chains between two pinned
  // particles: they cannot sag, and the projection has no room to move them back once they do.
  if (scene.params().pins == PinSet::corners)
    throw InputError(name_ + ": a sheet hung by its four corners cannot move when its structural springs are "
                     "constraints (each edge is a straight chain between two pins): expected --pins edge, corner, "
                     "none or clamped");
  free_count_ = scene.free_count();
  inverse_mass_ = 1.0 / scene.params().mass;
  const auto& springs = scene.springs();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = springs.family[static_cast<int>(family)];
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = springs.springs[static_cast<std::size_t>(k)];
      if (s.p >= free_count_ && s.q >= free_count_) continue;  // joins two pinned particles: never moves
      const double K = scene.stiffness(family), D = scene.damping(family);
      if (family == SpringFamily::flexion) soft_.push_back({s.p, s.q, s.rest_length, K, D});
      else constraints_.push_back({s.p, s.q, s.rest_length, K, D});
      if (family != SpringFamily::flexion && D != 0) soft_.push_back({s.p, s.q, s.rest_length, 0.0, D});  // damper
      if (family == SpringFamily::structural) ++hard_count_;
    }
  }
  const auto slots = static_cast<Eigen::Index>(scene.particle_count());
  X_ = scene.rest_positions().reshaped(3, slots);
  V_.setZero(3, slots);
  F_.setZero(3, slots);
  start_ = X_;
  const auto m = static_cast<Eigen::Index>(constraints_.size());
  u_.setZero(3, m);
  C_.setZero(m);
  alpha_tilde_.setZero(m);
  Lambda_.setZero(m);
  delta_.setZero(m);
  rhs_.setZero(m);
  build(all_, static_cast<int>(m));
  build(hard_, hard_count_);
}

void ConstrainedCloth::build(Gram& g, int count) {
  // The pattern (lower triangle): the diagonal, and one entry per pair of constraints sharing a free particle.
  std::vector<std::vector<std::pair<int, double>>> incident(static_cast<std::size_t>(free_count_));
  for (int c = 0; c < count; ++c) {
    const Link& l = constraints_[static_cast<std::size_t>(c)];
    if (l.p < free_count_) incident[static_cast<std::size_t>(l.p)].emplace_back(c, +1.0);
    if (l.q < free_count_) incident[static_cast<std::size_t>(l.q)].emplace_back(c, -1.0);
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(count));
  for (int c = 0; c < count; ++c) entries.emplace_back(c, c, 1.0);
  for (const auto& near : incident)
    for (const auto& [a, sa] : near)
      for (const auto& [b, sb] : near)
        if (a > b) {
          g.couplings.push_back({a, b, sa * sb * inverse_mass_, -1});
          entries.emplace_back(a, b, 0.0);
        }
  g.S.resize(count, count);
  g.S.setFromTriplets(entries.begin(), entries.end());
  g.S.makeCompressed();
  const auto index = [&g](int row, int column) {
    const auto* rows = g.S.innerIndexPtr();
    const auto begin = g.S.outerIndexPtr()[column], end = g.S.outerIndexPtr()[column + 1];
    return static_cast<int>(std::lower_bound(rows + begin, rows + end, row) - rows);
  };
  for (Coupling& k : g.couplings) k.value = index(k.a, k.b);
  for (int c = 0; c < count; ++c) g.diagonal.push_back(index(c, c));
  // A straight chain of structural springs between two pinned particles (an edge of the sheet hung by its corners)
  // can carry a tension the other constraints do not see, so J M^-1 J^T is singular at its straight state. A shift
  // of 1e-8 of the diagonal makes each solve a Levenberg-Marquardt step there; the iteration still drives the
  // residual itself to zero.
  g.solver.setShift(1e-8 * 2 * inverse_mass_);
  g.solver.analyzePattern(g.S);  // the ordering and the symbolic factorization, once per scene
}

bool ConstrainedCloth::factorize(Gram& g, int count) {
  double* values = g.S.valuePtr();
  for (int c = 0; c < count; ++c) {
    const Link& l = constraints_[static_cast<std::size_t>(c)];
    values[g.diagonal[static_cast<std::size_t>(c)]] = w(l.p) + w(l.q) + alpha_tilde_[c];  // |u|^2 = 1
  }
  for (const Coupling& k : g.couplings) values[k.value] = k.sign * u_.col(k.a).dot(u_.col(k.b));
  g.solver.factorize(g.S);
  ++counters_.factorizations;
  return g.solver.info() == Eigen::Success;
}

void ConstrainedCloth::soft_forces(const Slots& X, const Slots& V) {
  const Scene& scene = field_.scene();
  F_.setZero();
  F_.row(2).array() = -scene.params().mass * scene.params().gravity;
  for (const Link& s : soft_) {
    const Eigen::Vector3d d = X.col(s.p) - X.col(s.q);
    const double l = d.norm();
    if (l <= degenerate_length_fraction * s.rest_length) continue;
    const Eigen::Vector3d u = d / l;
    // The spring K (L0 - l) u and the projected damper -D ((v_p - v_q) . u) u (docs/model.md).
    const Eigen::Vector3d f = (s.K * (s.rest_length - l) - s.D * u.dot(V.col(s.p) - V.col(s.q))) * u;
    F_.col(s.p) += f;
    F_.col(s.q) -= f;
  }
}

void ConstrainedCloth::directions(const Slots& X) {
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    const Link& l = constraints_[c];
    const Eigen::Vector3d d = X.col(l.p) - X.col(l.q);
    const double length = d.norm();
    u_.col(static_cast<Eigen::Index>(c)) = d / length;
    C_[static_cast<Eigen::Index>(c)] = length - l.rest_length;
  }
}

void ConstrainedCloth::apply_gradient_transpose(const Vector& lambda, Slots& Y, int count) {
  for (int c = 0; c < count; ++c) {
    const Link& l = constraints_[static_cast<std::size_t>(c)];
    const Eigen::Vector3d g = lambda[c] * u_.col(c);
    Y.col(l.p) -= w(l.p) * g;
    Y.col(l.q) += w(l.q) * g;
  }
}

// [projection]
bool ConstrainedCloth::project_positions(bool along_start_gradients) {
  const int m = constraint_count();
  Lambda_.setZero();
  if (along_start_gradients) {  // SHAKE: u and the factorization stay those of x_n, C is taken at each iterate
    if (!factorize(all_, m)) return fail(StepFailureKind::factorization_singular, name_ + ": J M^-1 J^T singular");
  }
  for (int k = 0;; ++k) {
    if (along_start_gradients) {
      for (int c = 0; c < m; ++c) {
        const Link& l = constraints_[static_cast<std::size_t>(c)];
        C_[c] = (X_.col(l.p) - X_.col(l.q)).norm() - l.rest_length;
      }
    } else {
      directions(X_);  // u and C at the iterate x_k
    }
    rhs_ = C_ - alpha_tilde_.cwiseProduct(Lambda_);
    last_residual_ = m == 0 ? 0.0 : rhs_.cwiseAbs().maxCoeff();
    if (last_residual_ <= tolerance_) return true;
    if (k == max_iterations_)
      return fail(StepFailureKind::newton_not_converged,
                  name_ + ": constraint residual " + std::to_string(last_residual_) + " m after " +
                      std::to_string(k) + " projections");
    if (!along_start_gradients && !factorize(all_, m))
      return fail(StepFailureKind::factorization_singular, name_ + ": J M^-1 J^T singular");
    delta_ = all_.solver.solve(rhs_);
    ++counters_.linear_solves;
    ++counters_.newton_iterations;
    apply_gradient_transpose(delta_, X_, m);  // x_{k+1} = x_k - M^-1 J^T dLambda
    Lambda_ += delta_;
  }
}
// [projection]

bool ConstrainedCloth::fail(StepFailureKind kind, const std::string& reason) {
  failure_ = {kind, reason};
  return false;
}

bool ConstrainedCloth::step(double h, Vector& x, Vector& v) {
  const Eigen::Index n = free_count_;
  X_.leftCols(n) = x.reshaped(3, n);
  V_.leftCols(n) = v.reshaped(3, n);
  start_.leftCols(n) = X_.leftCols(n);
  const double compliance_scale = scheme_ == ConstrainedScheme::rattle ? 2 / (h * h) : 1 / (h * h);
  for (int c = hard_count_; c < constraint_count(); ++c)
    alpha_tilde_[c] = compliance_scale / constraints_[static_cast<std::size_t>(c)].K;
  if (scheme_ == ConstrainedScheme::fast_projection) {
    // [fast_projection_step]
    soft_forces(X_, V_);
    V_.leftCols(n) += (h * inverse_mass_) * F_.leftCols(n);  // symplectic Euler's prediction
    X_.leftCols(n) += h * V_.leftCols(n);
    if (!project_positions(false)) return false;
    V_.leftCols(n) = (X_.leftCols(n) - start_.leftCols(n)) / h;
    // [fast_projection_step]
  } else {
    // [rattle_step]
    soft_forces(X_, V_);
    directions(X_);  // J(x_n): SHAKE's directions
    X_.leftCols(n) += h * V_.leftCols(n) + (0.5 * h * h * inverse_mass_) * F_.leftCols(n);  // half kick, drift
    if (!project_positions(true)) return false;
    directions(X_);  // J(x_{n+1})
    V_.leftCols(n) = (X_.leftCols(n) - start_.leftCols(n)) / h;
    soft_forces(X_, V_);
    for (int c = hard_count_; c < constraint_count(); ++c) {  // the shear springs' force at x_{n+1}: -K C u
      const Link& l = constraints_[static_cast<std::size_t>(c)];
      const Eigen::Vector3d f = (-l.K * C_[c]) * u_.col(c);
      F_.col(l.p) += f;
      F_.col(l.q) -= f;
    }
    V_.leftCols(n) += (0.5 * h * inverse_mass_) * F_.leftCols(n);  // half kick
    // Onto the structural constraints' tangent space at x_{n+1}: J_s M^-1 J_s^T mu = J_s v*.
    for (int c = 0; c < hard_count_; ++c) {
      const Link& l = constraints_[static_cast<std::size_t>(c)];
      rhs_[c] = u_.col(c).dot(V_.col(l.p) - V_.col(l.q));
    }
    if (!factorize(hard_, hard_count_))
      return fail(StepFailureKind::factorization_singular, name_ + ": J M^-1 J^T of the structural springs singular");
    for (int pass = 0; pass < 2; ++pass) {  // the second pass removes what the solver's shift left
      if (pass == 1)
        for (int c = 0; c < hard_count_; ++c) {
          const Link& l = constraints_[static_cast<std::size_t>(c)];
          rhs_[c] = u_.col(c).dot(V_.col(l.p) - V_.col(l.q));
        }
      delta_.head(hard_count_) = hard_.solver.solve(rhs_.head(hard_count_));
      ++counters_.linear_solves;
      apply_gradient_transpose(delta_, V_, hard_count_);
    }
    // [rattle_step]
  }
  ++counters_.steps;
  ++counters_.rhs_evaluations;
  x = X_.leftCols(n).reshaped();
  v = V_.leftCols(n).reshaped();
  return true;
}

double ConstrainedCloth::largest_violation(const Vector& x) {
  X_.leftCols(free_count_) = x.reshaped(3, free_count_);
  directions(X_);
  return hard_count_ == 0 ? 0.0 : C_.head(hard_count_).cwiseAbs().maxCoeff();
}

double ConstrainedCloth::largest_stretching_rate(const Vector& x, const Vector& v) {
  X_.leftCols(free_count_) = x.reshaped(3, free_count_);
  V_.leftCols(free_count_) = v.reshaped(3, free_count_);
  directions(X_);
  double rate = 0;
  for (int c = 0; c < hard_count_; ++c) {
    const Link& l = constraints_[static_cast<std::size_t>(c)];
    rate = std::max(rate, std::abs(u_.col(c).dot(V_.col(l.p) - V_.col(l.q))));
  }
  return rate;
}

}  // namespace cloth
