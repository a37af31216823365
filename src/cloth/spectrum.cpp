// Eigenvalues of the linearised cloth and its sagged equilibrium, from the analytic Jacobians of ForceField.
#include "cloth/spectrum.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

namespace cloth {

Eigen::MatrixXd linearised_system(ForceField& field, const Vector& x, const Vector& v) {
  const int n = field.dof_count();
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, v, dfdx, dfdv);
  const double inv_m = 1.0 / field.scene().params().mass;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  J.topRightCorner(n, n).setIdentity();
  J.bottomLeftCorner(n, n) = inv_m * Eigen::MatrixXd(dfdx);
  J.bottomRightCorner(n, n) = inv_m * Eigen::MatrixXd(dfdv);
  return J;
}

std::vector<std::complex<double>> dense_spectrum(ForceField& field, const Vector& x, const Vector& v) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(linearised_system(field, x, v), false);
  const auto& values = solver.eigenvalues();
  return {values.data(), values.data() + values.size()};
}

std::vector<double> stiffness_eigenvalues(ForceField& field, const Vector& x) {
  const Vector v = Vector::Zero(x.size());
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, v, dfdx, dfdv);
  const Eigen::MatrixXd K = -Eigen::MatrixXd(dfdx) / field.scene().params().mass;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, Eigen::EigenvaluesOnly);
  const auto& values = solver.eigenvalues();
  return {values.data(), values.data() + values.size()};
}

std::array<std::complex<double>, 2> mode_eigenvalues(double omega2, double c) {
  const std::complex<double> root = std::sqrt(std::complex<double>(c * c - 4 * omega2, 0.0));
  return {0.5 * (-c + root), 0.5 * (-c - root)};
}

std::vector<std::complex<double>> proportional_spectrum(const std::vector<double>& omega2, double beta) {
  std::vector<std::complex<double>> lambda;
  lambda.reserve(2 * omega2.size());
  for (double w2 : omega2) {
    const auto pair = mode_eigenvalues(w2, beta * w2);
    lambda.push_back(pair[0]);
    lambda.push_back(pair[1]);
  }
  return lambda;
}

PowerIterationResult largest_eigenvalue_magnitude(ForceField& field, const Vector& x, const Vector& v,
                                                  double tolerance, int max_iterations) {
  const int n = field.dof_count();
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, v, dfdx, dfdv);
  const double inv_m = 1.0 / field.scene().params().mass;
  // J (a, b) = (b, M^{-1} (df/dx a + df/dv b)).
  const auto apply = [&](const Vector& y, Vector& out) {
    out.head(n) = y.tail(n);
    out.tail(n) = inv_m * (dfdx * y.head(n) + dfdv * y.tail(n));
  };
  // A fixed, non-special start: every mode present with comparable weight.
  Vector y0(2 * n), y1(2 * n), y2(2 * n);
  for (int k = 0; k < 2 * n; ++k) y0[k] = std::sin(1.0 + 0.7 * k) + 0.3 * std::cos(0.13 * k * k);
  y0.normalize();
  PowerIterationResult result;
  double previous = 0;
  for (int it = 1; it <= max_iterations; ++it) {
    apply(y0, y1);
    apply(y1, y2);
    // Least squares for (p, q) in y2 + p y1 + q y0 = 0: the 2 x 2 normal equations.
    const double a11 = y1.dot(y1), a12 = y1.dot(y0), a22 = y0.dot(y0);
    const double r1 = -y2.dot(y1), r2 = -y2.dot(y0);
    const double det = a11 * a22 - a12 * a12;
    double estimate = 0;
    if (std::abs(det) > 1e-14 * a11 * a22) {
      const double p = (r1 * a22 - r2 * a12) / det;
      const double q = (a11 * r2 - a12 * r1) / det;
      const auto roots = mode_eigenvalues(q, p);  // mu^2 + p mu + q = 0
      const auto top = std::abs(roots[0]) >= std::abs(roots[1]) ? roots[0] : roots[1];
      result.dominant = {top.real(), std::abs(top.imag())};
      estimate = std::abs(top);
    } else {
      estimate = std::sqrt(a11);  // y1 is parallel to y0: a real dominant eigenvalue, |J y0| = |lambda|
      result.dominant = y1.dot(y0) >= 0 ? estimate : -estimate;
    }
    result.magnitude = estimate;
    result.iterations = it;
    if (it % 10 == 0) {
      if (std::abs(estimate - previous) <= tolerance * estimate) {
        result.converged = true;
        break;
      }
      previous = estimate;
    }
    y0 = y2 / y2.norm();
  }
  return result;
}

Equilibrium static_equilibrium(ForceField& field, double tolerance, int max_iterations) {
  const Scene& scene = field.scene();
  const double m = scene.params().mass;
  const double limit = tolerance * m * std::max(scene.params().gravity, 1.0);
  const Vector zero = Vector::Zero(field.dof_count());
  Equilibrium eq;
  eq.x = scene.initial_positions();
  Vector f(field.dof_count()), trial(field.dof_count());
  SparseMatrix A = field.pattern();
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
  ldlt.analyzePattern(A);
  const auto potential = [&](const Vector& x) {
    const Energy e = field.energy(x, zero);
    return e.gravity + e.spring;
  };
  double energy = potential(eq.x);
  double tau = 0.05;
  for (eq.iterations = 0; eq.iterations < max_iterations; ++eq.iterations) {
    field.forces(eq.x, zero, f);
    eq.residual = f.lpNorm<Eigen::Infinity>();
    if (eq.residual <= limit) {
      eq.converged = true;
      break;
    }
    // Near the minimum, the exact Hessian (symmetric treatment) gives Newton's quadratic convergence; far from
    // it, compressed springs make it indefinite and the definite treatment keeps the step a descent direction.
    bool accepted = false;
    for (StiffnessTreatment treatment : {StiffnessTreatment::symmetric, StiffnessTreatment::definite}) {
      if (treatment == StiffnessTreatment::symmetric && tau < 10) continue;
      field.newton_matrix(eq.x, zero, tau, treatment, A);
      ldlt.factorize(A);
      if (ldlt.info() != Eigen::Success) continue;
      trial = eq.x + ldlt.solve(tau * tau * f);
      const double e = potential(trial);
      if (std::isfinite(e) && e <= energy + 1e-13 * (1 + std::abs(energy))) {
        eq.x = trial;
        energy = e;
        accepted = true;
        break;
      }
    }
    tau = accepted ? std::min(2 * tau, 1e6) : 0.25 * tau;
  }
  return eq;
}

}  // namespace cloth
