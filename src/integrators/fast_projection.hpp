// Inextensible cloth (Chapter 10): the springs whose stretch the motion never needs, held as exact distance
// constraints, and the rest kept as forces. Two steps on one set of constraints: Goldenthal, Harmon, Fattal,
// Bercovier and Grinspun's fast projection (2007) and the classical RATTLE (Andersen 1983), both projecting by
// Newton iterations with a sparse symmetric solve whose pattern is analysed once per scene.
#pragma once

#include "integrators/stepper.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <string>
#include <vector>

namespace cloth {

/// Which step the constrained cloth takes.
enum class ConstrainedScheme {
  /// Goldenthal et al. 2007: a symplectic Euler predictor in the forces, the prediction projected onto the
  /// constraints by Newton-like iterations along the current constraint gradients, v = (x_{n+1} - x_n) / h.
  /// First order.
  fast_projection,
  /// RATTLE: a half kick, a drift, the positions projected onto the constraints, a half kick, the velocity
  /// projected onto the structural constraints' tangent space. Second order in the hard constraints.
  rattle,
};

/// The constrained step. Constraints: every structural spring held at its rest length (hard), and every shear
/// spring as a compliant constraint C = alpha lambda with alpha = 1/K (lambda its tension), its own spring law solved implicitly.
/// Forces: gravity, the flexion springs, and every damper. A structural damper does no work (its stretching rate
/// is zero); a structural spring's force is its constraint's multiplier.
class ConstrainedCloth final : public Stepper {
 public:
  /// Throws InputError for a sheet pinned at its four corners (see fast_projection.cpp).
  /// `name` is the registry's name; `tolerance` the largest constraint residual |C - alpha~ Lambda| [m] a projected
  /// state may keep (|l - L0| for the structural springs).
  ConstrainedCloth(ForceField& field, std::string name, ConstrainedScheme scheme, double tolerance = 1e-10,
                   int max_iterations = 50);
  [[nodiscard]] std::string name() const override { return name_; }
  bool step(double h, Vector& x, Vector& v) override;

  /// The largest |l - L0| over the structural springs at the free positions x [m].
  [[nodiscard]] double largest_violation(const Vector& x);
  /// The largest |(v_p - v_q) . u| over the structural springs at (x, v) [m/s]: v's distance from their tangent
  /// space.
  [[nodiscard]] double largest_stretching_rate(const Vector& x, const Vector& v);
  /// The largest residual |C - alpha~ Lambda| the last step's projection left, over every constraint [m].
  [[nodiscard]] double last_residual() const { return last_residual_; }
  [[nodiscard]] int hard_constraint_count() const { return hard_count_; }
  [[nodiscard]] int constraint_count() const { return static_cast<int>(constraints_.size()); }
  [[nodiscard]] int soft_spring_count() const { return static_cast<int>(soft_.size()); }

 private:
  using Slots = Eigen::Matrix<double, 3, Eigen::Dynamic>;  // one column per particle slot, pinned ones last
  struct Link {       // a spring between slots p and q
    int p, q;
    double rest_length;
    double K = 0, D = 0;
  };
  struct Coupling {   // an off-diagonal entry of S = J M^-1 J^T: constraints a > b sharing one free particle
    int a, b;
    double sign;      // the product of the two gradients' signs at the shared particle, times its inverse mass
    int value;        // index of entry (a, b) in the matrix's value array
  };
  /// J M^-1 J^T + diag(alpha~) of the first `count` constraints, its pattern and ordering analysed once.
  struct Gram {
    SparseMatrix S;  // lower triangle
    std::vector<Coupling> couplings;
    std::vector<int> diagonal;  // index of entry (c, c)
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> solver;
  };

  [[nodiscard]] double w(int slot) const { return slot < free_count_ ? inverse_mass_ : 0.0; }
  void build(Gram& g, int count);
  bool factorize(Gram& g, int count);                    // at u_, with alpha_tilde_ on the diagonal
  void soft_forces(const Slots& X, const Slots& V);      // F_ = gravity + flexion springs + every damper
  void directions(const Slots& X);                       // u_ and C_ of every constraint at X
  void apply_gradient_transpose(const Vector& lambda, Slots& Y, int count);  // Y -= M^-1 J^T lambda
  bool project_positions(bool along_start_gradients);    // X_ onto C - alpha~ Lambda = 0
  bool fail(StepFailureKind kind, const std::string& reason);

  std::string name_;
  ConstrainedScheme scheme_;
  double tolerance_;
  int max_iterations_;
  int free_count_;
  int hard_count_ = 0;  // the structural constraints, first in constraints_
  double inverse_mass_;
  double last_residual_ = 0;
  std::vector<Link> constraints_, soft_;
  Slots X_, V_, F_, start_, u_;
  Vector C_, alpha_tilde_, Lambda_, delta_, rhs_;
  Gram all_, hard_;  // every constraint (positions); the structural ones (RATTLE's velocities)
};

}  // namespace cloth
