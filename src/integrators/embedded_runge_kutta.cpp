// An attempted step of an embedded pair: the stage loop of Chapter 3's engine, then two weighted sums, one for the
// candidate and one for the error estimate.
#include "integrators/embedded_runge_kutta.hpp"

#include "base/input_error.hpp"
#include "integrators/explicit_stage.hpp"

namespace cloth {

namespace {

// sum = h sum_i w_i u_i over the i with w_i != 0, started from its first term (no zero fill); a row with no
// nonzero weight gives zero.
void weighted_sum(double h, const Eigen::VectorXd& w, const std::vector<const Vector*>& u, Vector& sum) {
  bool first = true;
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    if (w[i] == 0.0) continue;
    const Vector& ui = *u[static_cast<std::size_t>(i)];
    if (first) {
      sum.noalias() = (h * w[i]) * ui;
      first = false;
    } else {
      sum.noalias() += (h * w[i]) * ui;
    }
  }
  if (first) sum.setZero();
}

}  // namespace

EmbeddedRungeKutta::EmbeddedRungeKutta(ForceField& field, ButcherTableau tableau)
    : Stepper(field), tableau_(std::move(tableau)) {
  validate(tableau_);
  if (!tableau_.has_embedded())
    throw InputError("tableau '" + tableau_.name + "' has no embedded row b-hat: it cannot estimate its error");
  d_ = tableau_.b - tableau_.b_hat;
  fsal_ = tableau_.first_same_as_last();
  const int n = field.dof_count();
  const auto s = static_cast<std::size_t>(tableau_.stages());
  stage_v_.assign(s, Vector(n));
  V_.assign(s, nullptr);
  stage_a_.assign(s, Vector(n));
  for (const Vector& ai : stage_a_) a_.push_back(&ai);
  stage_x_.resize(n);
  x_new_.resize(n);
  v_new_.resize(n);
  error_x_.resize(n);
  error_v_.resize(n);
}

const Vector& EmbeddedRungeKutta::first_stage(const Vector& x, const Vector& v) {
  if (!first_known_) {
    field_.acceleration(x, v, stage_a_[0]);
    ++counters_.rhs_evaluations;
    first_known_ = true;
  }
  return stage_a_[0];
}

void EmbeddedRungeKutta::attempt(double h, const Vector& x, const Vector& v) {
  const Eigen::MatrixXd& A = tableau_.A;
  const int s = tableau_.stages();
  first_stage(x, v);
  V_[0] = &v;
  // [embedded_attempt]
  for (int i = 1; i < s; ++i) {
    // X_i = x + h sum_{j<i} a_ij V_j, V_i = v + h sum_{j<i} a_ij a_j (as in ExplicitRungeKutta::step). The last
    // stage of a FSAL pair is formed where the candidate belongs: its row of A is b, so it is the candidate.
    const bool last_is_candidate = fsal_ && i == s - 1;
    Vector& Xi = last_is_candidate ? x_new_ : stage_x_;
    Vector& Vi = last_is_candidate ? v_new_ : stage_v_[static_cast<std::size_t>(i)];
    const bool formed = form_explicit_stage(A, i, h, x, v, V_, stage_a_, Xi, Vi);
    V_[static_cast<std::size_t>(i)] = formed ? &Vi : &v;
    field_.acceleration(formed ? Xi : x, formed ? Vi : v, stage_a_[static_cast<std::size_t>(i)]);
  }
  counters_.rhs_evaluations += s - 1;
  // x1 = x + h sum b_i V_i, v1 = v + h sum b_i a_i (already formed as the last stage of a FSAL pair)
  if (!fsal_) {
    weighted_sum(h, tableau_.b, V_, x_new_);
    x_new_ += x;
    weighted_sum(h, tableau_.b, a_, v_new_);
    v_new_ += v;
  }
  // e = h sum (b_i - bhat_i) k_i: the difference of the two solutions, formed without forming the second one
  weighted_sum(h, d_, V_, error_x_);
  weighted_sum(h, d_, a_, error_v_);
  // [embedded_attempt]
}

void EmbeddedRungeKutta::accept(Vector& x, Vector& v) {
  x.swap(x_new_);
  v.swap(v_new_);
  // The last stage was evaluated at the new state: it is the next first stage (swap, no copy).
  if (fsal_) stage_a_[0].swap(stage_a_[static_cast<std::size_t>(tableau_.stages() - 1)]);
  first_known_ = fsal_;
  ++counters_.steps;
}

bool EmbeddedRungeKutta::step(double h, Vector& x, Vector& v) {
  restart();  // the caller may have changed (x, v) since the last step
  attempt(h, x, v);
  accept(x, v);
  return true;
}

}  // namespace cloth
