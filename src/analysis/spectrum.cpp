// Eigenvalues of the linearised cloth and its sagged equilibrium, from the analytic Jacobians of ForceField.
#include "analysis/spectrum.hpp"

#include "analysis/sparse_operators.hpp"
#include "integrators/block_ldu.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Spectra/GenEigsSolver.h>
#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

std::array<std::complex<double>, 2> mode_eigenvalues(double omega2, double c) { return quadratic_roots(c, omega2); }

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

std::vector<double> largest_stiffness_eigenvalues(ForceField& field, const Vector& x, int count) {
  const int n = field.dof_count();
  count = std::clamp(count, 1, n - 2);
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, Vector::Zero(n), dfdx, dfdv);
  ScaledSparseProduct op(dfdx, -1.0 / field.scene().params().mass);
  Spectra::SymEigsSolver<ScaledSparseProduct> lanczos(op, count, std::min(n, std::max(2 * count + 1, 40)));
  lanczos.init();
  lanczos.compute(Spectra::SortRule::LargestAlge, 1000, 1e-10);
  const Vector values = lanczos.eigenvalues();  // descending; only the converged ones
  return {values.data(), values.data() + values.size()};
}

std::vector<std::complex<double>> largest_eigenvalues(ForceField& field, const Vector& x, const Vector& v, int count) {
  const int n = field.dof_count();
  count = std::clamp(count, 1, 2 * n - 4);
  SparseMatrix dfdx = field.pattern(), dfdv = field.pattern();
  field.jacobians(x, v, dfdx, dfdv);
  FirstOrderSystemProduct J(dfdx, dfdv, field.scene().params().mass);
  // One more than asked, so that a conjugate pair at the cut can be completed.
  const int wanted = count + 1;
  Spectra::GenEigsSolver<FirstOrderSystemProduct> arnoldi(J, wanted, std::min(2 * n, std::max(2 * wanted + 1, 30)));
  arnoldi.init();
  arnoldi.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
  if (arnoldi.info() != Spectra::CompInfo::Successful) return {};
  const auto values = arnoldi.eigenvalues();  // sorted by decreasing |lambda|
  std::vector<std::complex<double>> lambda(values.data(), values.data() + values.size());
  const bool splits_pair = static_cast<int>(lambda.size()) > count && lambda[count - 1].imag() != 0 &&
                           std::abs(lambda[count] - std::conj(lambda[count - 1])) <= 1e-8 * std::abs(lambda[count]);
  lambda.resize(std::min<std::size_t>(lambda.size(), splits_pair ? count + 1 : count));
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
  Vector y0(2 * n);
  for (int k = 0; k < 2 * n; ++k) y0[k] = std::sin(1.0 + 0.7 * k) + 0.3 * std::cos(0.13 * k * k);
  return dominant_eigenvalue(apply, std::move(y0), {tolerance, 10, max_iterations});
}

Equilibrium static_equilibrium(ForceField& field, double tolerance, int max_iterations) {
  const Scene& scene = field.scene();
  const SceneParams& p = scene.params();
  const double m = p.mass;
  // Converged when the net force on every particle is a small fraction of its weight, or down to the rounding of
  // the spring forces that cancel in it: a light cloth's weight can lie below that (1 mg against springs of 20 N),
  // where no iteration can reduce |f| further.
  const double spring_force = std::max(p.stiffness, p.flexion_stiffness.value_or(0.0)) * 2 * p.grid.d;
  const double limit = std::max(tolerance * m * std::max(p.gravity, 1.0),
                                64 * std::numeric_limits<double>::epsilon() * spring_force);
  const Vector zero = Vector::Zero(field.dof_count());
  Equilibrium eq;
  eq.x = scene.initial_positions();
  Vector f(field.dof_count()), step(field.dof_count()), trial(field.dof_count());
  SparseMatrix A = field.pattern();
  // The block solver made for this matrix (integrators/block_ldu.hpp): on a 60 x 60 cloth several times faster
  // than a scalar sparse LDL^T. It does not pivot; a step it cannot solve well is caught by the energy test.
  BlockLDU ldu;
  ldu.analyze(A, BlockLDU::Symmetry::symmetric);
  const auto potential = [&](const Vector& x) {
    const Energy e = field.energy(x, zero);
    return e.gravity + e.spring;
  };
  double energy = potential(eq.x);
  double tau = 0.05;
  const double exact_from_tau = 10;  // [s]: below it M / tau^2 dominates and the exact Hessian is not tried
  bool symmetric_rejected = false;  // the last iteration's exact-Hessian step would have raised the energy
  for (eq.iterations = 0; eq.iterations < max_iterations; ++eq.iterations) {
    field.forces(eq.x, zero, f);
    eq.residual = f.lpNorm<Eigen::Infinity>();
    if (eq.residual <= limit) {
      eq.converged = true;
      break;
    }
    // Near the minimum, the exact Hessian (symmetric treatment) gives Newton's quadratic convergence; far from
    // it, compressed springs make it indefinite and the definite treatment keeps the step a descent direction.
    // Where the exact step was just refused, the cloth is crossing a region of negative curvature (a stiff sheet
    // buckling out of the state it sagged into): the exact step is tried only every other iteration there, since
    // each refusal costs a factorization.
    double taken = 0;  // the fraction of the step taken: 1, 1/2, 1/4, or 0 when the energy would rise
    bool tried_symmetric = false, symmetric_taken = false;
    for (StiffnessTreatment treatment : {StiffnessTreatment::symmetric, StiffnessTreatment::definite}) {
      const bool symmetric = treatment == StiffnessTreatment::symmetric;
      if (symmetric && (tau < exact_from_tau || symmetric_rejected)) continue;
      tried_symmetric = tried_symmetric || symmetric;
      field.newton_matrix(eq.x, zero, tau, treatment, A);
      if (!ldu.factorize(A)) continue;
      ldu.solve(A, tau * tau * f, step);
      // The step, or failing that half or a quarter of it: a stiff sheet's Newton steps overshoot its sag, and
      // shortening them costs two energies where a smaller tau would cost factorizations.
      for (double alpha : {1.0, 0.5, 0.25}) {
        trial = eq.x + alpha * step;
        const double e = potential(trial);
        if (std::isfinite(e) && e <= energy + 1e-13 * (1 + std::abs(energy))) {
          eq.x = trial;
          energy = e;
          taken = alpha;
          break;
        }
      }
      // A definite step taken whole where the exact one was refused points down a direction of negative
      // curvature, along which the definite model underestimates how far the energy falls: on a 60 x 60 cloth
      // at K = 1e4 its steps grew only about 6% per iteration, for over a hundred iterations. Doubling the step
      // while the energy keeps falling crosses that region in a few (an energy each, no factorization).
      if (taken == 1.0 && !symmetric && tau >= exact_from_tau) {
        for (int doubling = 0; doubling < 8; ++doubling) {
          trial = eq.x + step;
          const double e = potential(trial);
          if (!std::isfinite(e) || e >= energy) break;
          eq.x = trial;
          energy = e;
          step *= 2;
        }
      }
      if (taken > 0) {
        symmetric_taken = symmetric;
        break;
      }
    }
    symmetric_rejected = tried_symmetric && taken > 0 && !symmetric_taken;
    if (taken == 1.0) tau = std::min(2 * tau, 1e6);
    else if (taken == 0.0) tau *= 0.25;
  }
  return eq;
}

}  // namespace cloth
