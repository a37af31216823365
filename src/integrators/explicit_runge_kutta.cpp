// The tableau becomes the loop: stage i is built from the earlier stages with row i of A, the step from all
// stages with b.
#include "integrators/explicit_runge_kutta.hpp"

#include "integrators/explicit_stage.hpp"

namespace cloth {

ExplicitRungeKutta::ExplicitRungeKutta(ForceField& field, ButcherTableau tableau)
    : Stepper(field), tableau_(std::move(tableau)) {
  validate(tableau_);
  const int n = field.dof_count();
  const auto s = static_cast<std::size_t>(tableau_.stages());
  stage_v_.assign(s, Vector(n));
  V_.assign(s, nullptr);
  stage_a_.assign(s, Vector(n));
  stage_x_.resize(n);
  sum_v_.resize(n);
  sum_a_.resize(n);
  // b = e_i: the step is x + h V_i, v + h a_i, with no weighted sums to form (explicit Euler then costs what
  // the two lines x += h v, v += h a cost, and gives their bits).
  if ((tableau_.b.array() != 0.0).count() == 1) {
    Eigen::Index i = 0;
    tableau_.b.cwiseAbs().maxCoeff(&i);
    if (tableau_.b[i] == 1.0) only_stage_ = static_cast<int>(i);
  }
}

bool ExplicitRungeKutta::step(double h, Vector& x, Vector& v) {
  const Eigen::MatrixXd& A = tableau_.A;
  const Eigen::VectorXd& b = tableau_.b;
  const int s = tableau_.stages();
  // [rk_stage_loop]
  for (int i = 0; i < s; ++i) {
    // X_i = x + h sum_{j<i} a_ij V_j,  V_i = v + h sum_{j<i} a_ij a_j; a stage whose row of A is zero (the first,
    // always) evaluates at (x, v) itself.
    Vector& Vi = stage_v_[static_cast<std::size_t>(i)];
    const bool formed = form_explicit_stage(A, i, h, x, v, V_, stage_a_, stage_x_, Vi);
    V_[static_cast<std::size_t>(i)] = formed ? &Vi : &v;
    field_.acceleration(formed ? stage_x_ : x, formed ? Vi : v, stage_a_[static_cast<std::size_t>(i)]);
  }
  // x1 = x + h sum_i b_i V_i,  v1 = v + h sum_i b_i a_i
  if (only_stage_ >= 0) {  // b = e_i: the step is stage i's own slope
    const auto i = static_cast<std::size_t>(only_stage_);
    x.noalias() += h * *V_[i];
    v.noalias() += h * stage_a_[i];
  } else {
    // The sums start from their first term rather than from zero (0 + (-0) would turn a negative zero positive).
    bool first = true;
    for (int i = 0; i < s; ++i) {
      if (b[i] == 0.0) continue;
      const Vector& Vi = *V_[static_cast<std::size_t>(i)];
      const Vector& ai = stage_a_[static_cast<std::size_t>(i)];
      if (first) {
        sum_v_.noalias() = b[i] * Vi;
        sum_a_.noalias() = b[i] * ai;
        first = false;
      } else {
        sum_v_.noalias() += b[i] * Vi;
        sum_a_.noalias() += b[i] * ai;
      }
    }
    x.noalias() += h * sum_v_;
    v.noalias() += h * sum_a_;
  }
  // [rk_stage_loop]
  counters_.rhs_evaluations += s;
  ++counters_.steps;
  return true;
}

}  // namespace cloth
