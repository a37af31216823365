// The stage arguments of an explicit Runge-Kutta method on y = (x, v), y' = (v, a(x, v)): one routine that the
// fixed-step engine (Chapter 3) and the embedded pairs (Chapter 8) share, so both form a stage the same way.
#pragma once

#include "integrators/stepper.hpp"

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace cloth {

/// Forms stage i's arguments from the stages before it (Hairer, Norsett and Wanner, eq. II.1.8, written for the
/// split state):  X_i = x + h sum_{j<i} a_ij V_j,  V_i = v + h sum_{j<i} a_ij a_j.
/// Zero a_ij cost nothing, and the first non-zero one is added as X_i and V_i are formed (one pass over the
/// vectors, not a copy and then a pass). Returns false, leaving X_i and V_i untouched, when row i of A has no
/// non-zero entry: the stage then evaluates at (x, v) itself, with no copy at all.
inline bool form_explicit_stage(const Eigen::MatrixXd& A, int i, double h, const Vector& x, const Vector& v,
                                const std::vector<const Vector*>& V, const std::vector<Vector>& a, Vector& Xi,
                                Vector& Vi) {
  // [form_explicit_stage]
  bool formed = false;
  for (int j = 0; j < i; ++j) {
    if (A(i, j) == 0.0) continue;
    const double ha = h * A(i, j);
    const Vector& Vj = *V[static_cast<std::size_t>(j)];
    const Vector& aj = a[static_cast<std::size_t>(j)];
    if (!formed) {
      Xi.noalias() = x + ha * Vj;
      Vi.noalias() = v + ha * aj;
      formed = true;
    } else {
      Xi.noalias() += ha * Vj;
      Vi.noalias() += ha * aj;
    }
  }
  // [form_explicit_stage]
  return formed;
}

}  // namespace cloth
