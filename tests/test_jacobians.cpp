// The analytic Jacobians df/dx, df/dv of cloth::ForceField against central differences of its forces, for every
// damping law, and the Newton matrix A = M - h df/dv - h^2 df/dx in its three treatments: exact (assembled from
// the Jacobians), symmetric (symmetric), definite (positive definite where the exact matrix is not).
#include <doctest/doctest.h>

#include "model/force_field.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>

#include "random_state.hpp"

using namespace cloth;

namespace {

using testing::random_state;
using testing::State;
using testing::unit_roundoff;

SceneParams scene_params(PinSet pins, double K, double D, DampingModel model) {
  SceneParams p;
  p.grid = Grid{4, 5, 0.1};
  p.pins = pins;
  p.stiffness = K;
  p.damping = D;
  p.damping_model = model;
  return p;  // gravity on: it is constant, so it must drop out of every Jacobian
}

// Column k of a Jacobian of f by central differences in x (wrt_x) or in v.
Eigen::MatrixXd finite_difference_jacobian(ForceField& field, const State& s, bool wrt_x, double eps) {
  const Eigen::Index n = s.x.size();
  Eigen::MatrixXd J(n, n);
  Vector x = s.x, v = s.v, f_plus(n), f_minus(n);
  Vector& moved = wrt_x ? x : v;
  const Vector& base = wrt_x ? s.x : s.v;
  for (Eigen::Index k = 0; k < n; ++k) {
    moved[k] = base[k] + eps;
    field.forces(x, v, f_plus);
    moved[k] = base[k] - eps;
    field.forces(x, v, f_minus);
    moved[k] = base[k];
    J.col(k) = (f_plus - f_minus) / (2 * eps);
  }
  return J;
}

// The shortest spring, the largest rest length and the largest relative speed of a state, which bound the
// derivatives of the forces.
struct Extremes {
  double l_min = 1e300, L0_max = 0, l_max = 0, w_max = 0;
};
Extremes extremes(const Scene& scene, const State& s) {
  Vector X = scene.rest_positions();
  Vector V = Vector::Zero(X.size());
  X.head(s.x.size()) = s.x;
  V.head(s.v.size()) = s.v;
  Extremes e;
  for (const Spring& sp : scene.springs().springs) {
    const double l = (X.segment<3>(3 * sp.p) - X.segment<3>(3 * sp.q)).norm();
    e.l_min = std::min(e.l_min, l);
    e.l_max = std::max(e.l_max, l);
    e.L0_max = std::max(e.L0_max, sp.rest_length);
    e.w_max = std::max(e.w_max, (V.segment<3>(3 * sp.p) - V.segment<3>(3 * sp.q)).norm());
  }
  return e;
}

double max_abs(const Eigen::MatrixXd& A) { return A.cwiseAbs().maxCoeff(); }

}  // namespace

TEST_CASE("df/dx and df/dv equal central differences of the forces, undamped and for both damping laws") {
  std::mt19937 rng(11);
  struct Law {
    const char* name;
    double D;
    DampingModel model;
  };
  const Law laws[] = {{"undamped", 0.0, DampingModel::projected},
                      {"projected damper", 5.0, DampingModel::projected},
                      {"report damper", 5.0, DampingModel::report}};
  const double K = 50.0;
  for (const Law& law : laws) {
    const Scene scene(scene_params(PinSet::corners, K, law.D, law.model));
    ForceField field(scene);
    SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
    for (double scale : {0.75, 1.0, 1.25}) {
      CAPTURE(law.name);
      CAPTURE(scale);
      const State s = random_state(scene, rng, scale, 0.1, 2.0);
      field.jacobians(s.x, s.v, dfdx, dfdv);
      const Eigen::MatrixXd Jx = dfdx, Jv = dfdv;

      // Error bounds of the central difference (f(y + eps) - f(y - eps)) / (2 eps), y one coordinate.
      // Truncation, eps^2/6 |f'''|: the spring force K L0 u - K (x_p - x_q) has third derivatives of
      // K L0 u = K L0 d/|d| below 15 K L0 / l^3; the projected damper -D (w.u) u below 48 D |w| / l^3 (product
      // rule on u u^T); the report damper -D w l below 3 D |w| / l^2. An entry collects at most 12 springs.
      // Rounding: a force is a sum of at most 13 terms (12 springs and the weight) of size below F, so each
      // evaluation is off by less than 20 u F, and the quotient by less than 20 u F / eps. f is linear in v, so
      // df/dv by central differences has no truncation error at all.
      const Extremes e = extremes(scene, s);
      const double eps = 1e-6;
      const double l3 = e.l_min * e.l_min * e.l_min;
      const double third = 12 * (15 * K * e.L0_max / l3 + 48 * law.D * e.w_max / l3 +
                                 3 * law.D * e.w_max / (e.l_min * e.l_min));
      const double F = K * std::max(e.l_max, e.L0_max) + law.D * e.w_max * std::max(1.0, e.l_max) + 9.81;
      const double rounding = 20 * unit_roundoff * F / eps;
      const double tol_x = eps * eps / 6 * third + rounding;
      CAPTURE(tol_x);
      CAPTURE(rounding);
      REQUIRE(tol_x < 1e-3 * K);  // far below the entries (of order K), so a wrong term cannot hide

      const Eigen::MatrixXd Jx_fd = finite_difference_jacobian(field, s, true, eps);
      const Eigen::MatrixXd Jv_fd = finite_difference_jacobian(field, s, false, eps);
      CHECK(max_abs(Jx - Jx_fd) <= tol_x);
      CHECK(max_abs(Jv - Jv_fd) <= rounding);
      if (law.D == 0.0) CHECK(max_abs(Jv) == 0.0);
      else CHECK(max_abs(Jv) > 1.0);
      // The damper's position derivative is not symmetric, the undamped Hessian is.
      if (law.D == 0.0) CHECK(max_abs(Jx - Jx.transpose()) <= 1e-12 * max_abs(Jx));
      else CHECK(max_abs(Jx - Jx.transpose()) > 1e-3 * max_abs(Jx));
    }
  }
}

TEST_CASE("the exact Newton matrix is M - h df/dv - h^2 df/dx and the symmetric one drops only the damper's d/dx") {
  std::mt19937 rng(12);
  const double h = 0.01, K = 200.0, D = 20.0, m = 1.0;
  for (DampingModel model : {DampingModel::projected, DampingModel::report}) {
    CAPTURE(damping_model_name(model));
    const Scene scene(scene_params(PinSet::corners, K, D, model));
    ForceField field(scene);
    // The same cloth undamped: its df/dx is the spring force's Jacobian alone, minus the energy's Hessian.
    const Scene undamped_scene(scene_params(PinSet::corners, K, 0.0, model));
    ForceField undamped(undamped_scene);
    SparseMatrix dfdx = field.pattern(), dfdv = field.pattern(), A = field.pattern();
    SparseMatrix springs_dfdx = undamped.pattern(), zero_dfdv = undamped.pattern();
    const State s = random_state(scene, rng, 0.9, 0.2, 2.0);
    field.jacobians(s.x, s.v, dfdx, dfdv);
    undamped.jacobians(s.x, s.v, springs_dfdx, zero_dfdv);
    const Eigen::MatrixXd M = m * Eigen::MatrixXd::Identity(scene.dof_count(), scene.dof_count());

    field.newton_matrix(s.x, s.v, h, StiffnessTreatment::exact, A);
    const Eigen::MatrixXd exact = A;
    const Eigen::MatrixXd assembled = M - h * Eigen::MatrixXd(dfdv) - h * h * Eigen::MatrixXd(dfdx);
    CHECK(max_abs(exact - assembled) <= 1e-14 * max_abs(assembled));
    CHECK(max_abs(exact - exact.transpose()) > 1e-6);  // the damper makes the exact matrix non-symmetric

    field.newton_matrix(s.x, s.v, h, StiffnessTreatment::symmetric, A);
    const Eigen::MatrixXd sym = A;
    CHECK(max_abs(sym - sym.transpose()) <= 1e-14 * max_abs(sym));
    const Eigen::MatrixXd expected = M - h * Eigen::MatrixXd(dfdv) - h * h * Eigen::MatrixXd(springs_dfdx);
    CHECK(max_abs(sym - expected) <= 1e-14 * max_abs(expected));

    // Undamped, symmetric is exact.
    SparseMatrix B = undamped.pattern(), C = undamped.pattern();
    undamped.newton_matrix(s.x, s.v, h, StiffnessTreatment::exact, B);
    undamped.newton_matrix(s.x, s.v, h, StiffnessTreatment::symmetric, C);
    CHECK(max_abs(Eigen::MatrixXd(B) - Eigen::MatrixXd(C)) == 0.0);
  }
}

TEST_CASE("the definite Newton matrix is symmetric positive definite on a compressed cloth where exact is not") {
  const double K = 50.0, D = 2.0, m = 1.0, h = 0.1;
  // The sheet squeezed in-plane to half its size (and slightly crumpled so it is not planar): every spring is
  // at half its rest length, so its transverse stiffness K (1 - L0/l) = -K is negative.
  SceneParams p = scene_params(PinSet::none, K, D, DampingModel::projected);
  const Scene scene(p);
  ForceField field(scene);
  std::mt19937 rng(13);
  const State s = random_state(scene, rng, 0.5, 0.01, 1.0);

  // -df/dx of the undamped cloth is the energy's Hessian: here it has negative eigenvalues.
  p.damping = 0.0;
  const Scene undamped_scene(p);
  ForceField undamped(undamped_scene);
  SparseMatrix dfdx = undamped.pattern(), dfdv = undamped.pattern();
  undamped.jacobians(s.x, s.v, dfdx, dfdv);
  const Eigen::MatrixXd hessian = -Eigen::MatrixXd(dfdx);
  const double hessian_min = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hessian).eigenvalues().minCoeff();
  CAPTURE(hessian_min);
  CHECK(hessian_min < -m / (h * h));  // so negative that M + h^2 Hessian is indefinite at this h

  SparseMatrix A = field.pattern();
  field.newton_matrix(s.x, s.v, h, StiffnessTreatment::symmetric, A);
  const Eigen::MatrixXd sym = A;
  CHECK(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(sym).eigenvalues().minCoeff() < 0.0);
  CHECK(Eigen::LLT<Eigen::MatrixXd>(sym).info() == Eigen::NumericalIssue);

  field.newton_matrix(s.x, s.v, h, StiffnessTreatment::definite, A);
  const Eigen::MatrixXd def = A;
  CHECK(max_abs(def - def.transpose()) <= 1e-14 * max_abs(def));
  CHECK(Eigen::LLT<Eigen::MatrixXd>(def).info() == Eigen::Success);
  // Sharper: the kept spring terms K u u^T and the damper's h D u u^T are positive semidefinite, so
  // A = M + (positive semidefinite) has no eigenvalue below the mass.
  const double def_min = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(def).eigenvalues().minCoeff();
  CAPTURE(def_min);
  CHECK(def_min >= m * (1 - 1e-12));
}

TEST_CASE("on a uniformly stretched cloth the definite treatment changes nothing") {
  // Every spring stretched by 30 %: no transverse term is negative, so definite = symmetric = exact undamped.
  const Scene scene(scene_params(PinSet::none, 50.0, 0.0, DampingModel::projected));
  ForceField field(scene);
  Vector x = scene.initial_positions();
  for (Eigen::Index k = 0; k < x.size(); ++k)
    if (k % 3 != 2) x[k] *= 1.3;
  const Vector v = scene.initial_velocities();
  SparseMatrix A = field.pattern(), B = field.pattern();
  field.newton_matrix(x, v, 0.05, StiffnessTreatment::exact, A);
  field.newton_matrix(x, v, 0.05, StiffnessTreatment::definite, B);
  CHECK(max_abs(Eigen::MatrixXd(A) - Eigen::MatrixXd(B)) == 0.0);
  CHECK(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues().minCoeff() >= 1.0 - 1e-12);
}
