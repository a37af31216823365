// The DIRK engine: stages one after another, each an implicit Euler equation for its velocity.
#include "integrators/diagonally_implicit_runge_kutta.hpp"

#include <algorithm>

namespace cloth {

DiagonallyImplicitRungeKutta::DiagonallyImplicitRungeKutta(ForceField& field, ImplicitTableau tableau,
                                                           NewtonSettings settings)
    : NewtonStepper(field, settings), tableau_(std::move(tableau)) {
  validate(tableau_);
  const int s = tableau_.method.stages();
  const int n = field.dof_count();
  V_.assign(static_cast<std::size_t>(s), Vector::Zero(n));
  F_.assign(static_cast<std::size_t>(s), Vector::Zero(n));
  x_tilde_.resize(n), v_tilde_.resize(n);
  last_force_.resize(n), x_last_.resize(n), v_last_.resize(n);
  if (settings.dense_output_predictor && tableau_.stiffly_accurate()) {
    for (DenseOutput* d : {&last_, &before_}) d->v0 = d->a0 = d->x1 = d->v1 = d->a1 = Vector::Zero(n);
    v_start_ = dense_guess_ = force_guess_ = Vector::Zero(n);
  }
  if (tableau_.has_embedded()) error_x_ = Vector::Zero(n), error_v_ = Vector::Zero(n);
  // F_i is needed when a later stage uses it, when the weights combine it (a stiffly accurate method takes the
  // last stage instead), or when the embedded weights do. Otherwise its evaluation is skipped.
  const Eigen::MatrixXd& A = tableau_.method.A;
  for (int i = 0; i < s; ++i) {
    bool used = !tableau_.stiffly_accurate() && tableau_.method.b[i] != 0.0;
    for (int j = i + 1; j < s; ++j) used = used || A(j, i) != 0.0;
    if (tableau_.has_embedded()) used = used || tableau_.method.b_hat[i] != tableau_.method.b[i];
    need_force_.push_back(used);
  }
}

// [dense_output_predictor]
void DiagonallyImplicitRungeKutta::predict(const DenseOutput& d, double theta, Vector& V) {
  // The cubic Hermite interpolant of v on the step d (Hairer, Norsett & Wanner 1993, II.6): the one cubic with
  // v and v' = a at both ends, at t0 + theta h_d. Beyond the step (theta > 1) it extrapolates, with an error
  // O(h^4) for a smooth motion.
  const double t2 = theta * theta, t3 = t2 * theta;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + theta, h01 = 3 * t2 - 2 * t3, h11 = t3 - t2;
  V = h00 * d.v0 + h01 * d.v1 + (h10 * d.h) * d.a0 + (h11 * d.h) * d.a1;
}
// [dense_output_predictor]

// The tableau's name, as the registry's row: the Newton variant and the solver are settings, written beside it.
std::string DiagonallyImplicitRungeKutta::name() const { return tableau_.method.name; }

bool DiagonallyImplicitRungeKutta::step(double h, Vector& x, Vector& v) {
  const ButcherTableau& t = tableau_.method;
  const int s = t.stages();
  const double m = field_.scene().params().mass;
  newton_.begin_step();
  // The force the first implicit stage's guess starts from: the last one of the step before, if this step
  // continues it (a state set from outside, or a first step, has none).
  const Vector* latest_force = have_last_force_ && x == x_last_ && v == v_last_ ? &last_force_ : nullptr;
  const bool forces_free = !settings().one_iteration();  // Newton's last residual evaluated f(X_i, V_i)
  // The dense output this step continues: the last step's, or after a rejected step the one before it. The
  // one-iteration step keeps its own start: its single update is Baraff and Witkin's linearisation at the step's
  // state, so a predicted start would change the method, not only the work of reaching its solution.
  const bool dense = settings().dense_output_predictor && tableau_.stiffly_accurate() && !settings().one_iteration();
  const DenseOutput* previous = nullptr;
  if (dense) {
    for (const DenseOutput* d : {&last_, &before_})
      if (previous == nullptr && d->valid && x == d->x1 && v == d->v1) previous = d;
    v_start_ = v;
  }
  // How far the cubic may be taken, in lengths of the step it comes from (theta = 1 is its end): further than two
  // of them beyond its end it magnifies the rounding and Newton errors of its data, and the step control never
  // grows h that fast.
  constexpr double max_reach = 3.0;
  double dense_miss = 0, force_miss = 0;  // each guess's largest distance from its solved stage
  // [dirk_stages]
  for (int i = 0; i < s; ++i) {
    const auto si = static_cast<std::size_t>(i);
    // The stage's starting point: x~ = x0 + h sum_{j<i} a_ij V_j, v~ = v0 + (h/m) sum_{j<i} a_ij F_j.
    x_tilde_ = x;
    v_tilde_ = v;
    for (int j = 0; j < i; ++j) {
      const double a = t.A(i, j);
      if (a == 0.0) continue;
      x_tilde_ += (h * a) * V_[static_cast<std::size_t>(j)];
      v_tilde_ += (h * a / m) * F_[static_cast<std::size_t>(j)];
    }
    const double gamma = h * t.A(i, i);
    if (gamma == 0.0) {
      // An explicit stage (the first of an ESDIRK): its value is its starting point.
      V_[si] = v_tilde_;
      if (need_force_[si] || i + 1 == s) {
        field_.forces(x_tilde_, V_[si], F_[si]);
        ++counters_.rhs_evaluations;
        latest_force = &F_[si];
      }
      continue;
    }
    // The guess (the predictor): the previous step's dense output at the stage's time t + c_i h; without one,
    // the stage equation M (V - v~) = gamma f with the latest known force for f, which is off by gamma times the
    // change of the force since then, O(h^2); without that either, v~ itself.
    if (latest_force != nullptr) V_[si] = v_tilde_ + (gamma / m) * *latest_force;
    else V_[si] = v_tilde_;
    const double theta = previous != nullptr ? 1 + t.c[i] * h / previous->h : 0.0;
    const bool both = previous != nullptr && theta <= max_reach;
    if (both) {
      force_guess_ = V_[si];
      predict(*previous, theta, dense_guess_);
      if (dense_closer_) V_[si] = dense_guess_;
    }
    if (!newton_.solve(x_tilde_, v_tilde_, gamma, V_[si], need_force_[si])) {
      failure_ = newton_.failure();
      if (s > 1) failure_.reason = "stage " + std::to_string(i + 1) + ": " + failure_.reason;
      have_last_force_ = false;
      return false;
    }
    if (need_force_[si] || forces_free) {
      F_[si] = newton_.force();
      latest_force = &F_[si];
    }
    if (both) {
      dense_miss = std::max(dense_miss, (V_[si] - dense_guess_).lpNorm<Eigen::Infinity>());
      force_miss = std::max(force_miss, (V_[si] - force_guess_).lpNorm<Eigen::Infinity>());
    }
  }
  // [dirk_stages]
  if (tableau_.has_embedded()) {
    error_x_.setZero();
    error_v_.setZero();
    for (int i = 0; i < s; ++i) {
      const double e = t.b[i] - t.b_hat[i];
      if (e == 0.0) continue;
      error_x_ += (h * e) * V_[static_cast<std::size_t>(i)];
      error_v_ += (h * e / m) * F_[static_cast<std::size_t>(i)];
    }
  }
  if (tableau_.stiffly_accurate()) {
    // The last stage is the step: x1 = x~_s + h a_ss V_s, as Newton computed it.
    const auto last = static_cast<std::size_t>(s - 1);
    if (t.A(s - 1, s - 1) != 0.0) x = newton_.position();
    else x = x_tilde_;
    v = V_[last];
  } else {
    for (int i = 0; i < s; ++i) {
      const double b = t.b[i];
      if (b == 0.0) continue;
      x += (h * b) * V_[static_cast<std::size_t>(i)];
      v += (h * b / m) * F_[static_cast<std::size_t>(i)];
    }
  }
  have_last_force_ = latest_force != nullptr;
  if (have_last_force_) {
    last_force_ = *latest_force;
    x_last_ = x;
    v_last_ = v;
  }
  if (dense_miss > 0 || force_miss > 0) dense_closer_ = dense_miss < force_miss;
  if (dense) record_dense_output(h, x, v, previous);
  ++counters_.steps;
  return true;
}

void DiagonallyImplicitRungeKutta::record_dense_output(double h, const Vector& x, const Vector& v,
                                                       const DenseOutput* previous) {
  // The step's accelerations at its ends: the explicit first stage's force at its start (or the end force of the
  // step it continues) and, the tableau being stiffly accurate, the last stage's force at its end.
  const ButcherTableau& t = tableau_.method;
  const int s = t.stages();
  const double m = field_.scene().params().mass;
  const bool start_known = (t.A(0, 0) == 0.0 && need_force_[0]) || previous != nullptr;
  const bool end_known = need_force_[static_cast<std::size_t>(s - 1)] || !settings().one_iteration();
  // The step continued `previous`: that one becomes the step before; otherwise there is none.
  if (previous == &last_) std::swap(last_, before_);
  else if (previous == nullptr) before_.valid = false;
  DenseOutput& d = last_;
  d.valid = start_known && end_known && t.A(s - 1, s - 1) != 0.0;
  if (!d.valid) return;
  d.h = h;
  d.v0 = v_start_;
  if (t.A(0, 0) == 0.0 && need_force_[0]) d.a0 = F_[0] / m;
  else d.a0 = before_.a1;
  d.x1 = x;
  d.v1 = v;
  d.a1 = F_[static_cast<std::size_t>(s - 1)] / m;
}

}  // namespace cloth
