// Extended position-based dynamics (XPBD; Macklin, Müller & Chentanez 2016) and its "small steps" schedule
// (Macklin, Storey, Lu, Terdiman, Chentanez, Jeschke & Müller 2019), Chapter 10: every spring a compliant distance
// constraint, projected one at a time (Gauss-Seidel) around an inertial prediction. What real-time cloth ships.
#pragma once

#include "contact/obstacles.hpp"
#include "integrators/stepper.hpp"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cloth {

/// One XPBD projection of the distance constraint C = |x_p - x_q| - L0 (Macklin et al. 2016, eq. (26)): the
/// multiplier change
///   dlambda = (-C - alpha~ lambda - gamma grad C . (x - x^n)) / ((1 + gamma) (w_p + w_q) + alpha~),
/// then x_p += w_p dlambda u and x_q -= w_q dlambda u: the update M^-1 grad C^T dlambda, with grad_p C = u =
/// (x_p - x_q) / |x_p - x_q|.
/// w are inverse masses (0 for a pinned particle), alpha~ = alpha / h^2 the compliance over the step squared,
/// gamma = alpha~ beta~ / h the damping ratio, `previous_p - previous_q` the spring vector at the start of the
/// step x^n. Adds dlambda to `lambda` and returns it; a spring shorter than degenerate_length_fraction L0 has no
/// direction and is left alone (returns 0), as the force routine leaves it.
inline double project_distance_constraint(Eigen::Ref<Eigen::Vector3d> x_p, Eigen::Ref<Eigen::Vector3d> x_q,
                                          const Eigen::Vector3d& previous_p, const Eigen::Vector3d& previous_q,
                                          double w_p, double w_q, double rest_length, double alpha_tilde,
                                          double gamma, double& lambda) {
  const Eigen::Vector3d d = x_p - x_q;
  const double l = d.norm();
  if (l <= degenerate_length_fraction * rest_length) return 0.0;
  const Eigen::Vector3d u = d / l;
  const double C = l - rest_length;
  const double stretching = u.dot((x_p - previous_p) - (x_q - previous_q));  // grad C . (x - x^n)
  const double dlambda = (-C - alpha_tilde * lambda - gamma * stretching) / ((1 + gamma) * (w_p + w_q) + alpha_tilde);
  lambda += dlambda;
  x_p += (w_p * dlambda) * u;
  x_q -= (w_q * dlambda) * u;
  return dlambda;
}

/// XPBD's step, `substeps` substeps of h / substeps, each an inertial prediction followed by `iterations`
/// Gauss-Seidel sweeps over the springs. The registry's `xpbd` (many iterations, few substeps) and `small_steps`
/// (one iteration, many substeps) are this stepper with different settings.
class Xpbd final : public Stepper {
 public:
  /// `name` is the registry's name of the configuration; iterations and substeps >= 1. Throws InputError for the
  /// report's damping law, which is not a damper along the constraint (see xpbd.cpp).
  Xpbd(ForceField& field, std::string name, int iterations, int substeps);
  [[nodiscard]] std::string name() const override { return name_; }
  bool step(double h, Vector& x, Vector& v) override;

  [[nodiscard]] int iterations() const { return iterations_; }
  [[nodiscard]] int substeps() const { return substeps_; }

  /// Contact as inequality constraints phi(x) >= thickness (Chapter 11), projected with their friction at the
  /// end of every substep's sweeps, so that the velocity the substep derives from its positions has stopped at
  /// the obstacle; null (the default) for none. The model must outlive the stepper.
  void set_contact(const ContactModel* contact) { contact_ = contact; }

 private:
  void substep(double s);

  using Slots = Eigen::Matrix<double, 3, Eigen::Dynamic>;  // one column per particle slot, pinned ones last

  std::string name_;
  int iterations_;
  int substeps_;
  int free_count_;
  double inverse_mass_;
  Slots X_;         // positions of every slot: the free ones iterated, the pinned tail at rest
  Slots previous_;  // x^n, the positions at the start of the substep
  Slots V_;         // velocities of the free slots (the pinned tail stays 0)
  std::vector<double> lambda_;  // each spring's multiplier, summed over the substep's iterations
  Vector bending_force_;        // the bending term's force at the substep's start, when the scene has one
  const ContactModel* contact_ = nullptr;
};

}  // namespace cloth
