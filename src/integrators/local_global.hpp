// Implicit Euler by local/global iterations (Liu, Bargteil, O'Brien & Kavan 2013, "Fast Simulation of
// Mass-Spring Systems"), Chapter 10: each iteration projects every spring onto its rest length (local) and then
// solves one linear system whose matrix M + h^2 L does not depend on the state (global), factored once per step
// size. It is what practitioners ship for real-time cloth; it converges to implicit Euler's solution.
#pragma once

#include "integrators/stepper.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <string>

namespace cloth {

class LocalGlobal final : public Stepper {
 public:
  /// `iterations` local/global iterations per step (Liu et al. use about 10), >= 1.
  LocalGlobal(ForceField& field, int iterations);
  [[nodiscard]] std::string name() const override;
  bool step(double h, Vector& x, Vector& v) override;

  [[nodiscard]] int iterations() const { return iterations_; }

 private:
  // Factors M + h^2 L (one scalar matrix for the three coordinates) and the pinned particles' constant pull.
  bool factor(double h);

  using Coordinates = Eigen::Matrix<double, Eigen::Dynamic, 3>;  // one row (x, y, z) per free particle

  int iterations_;
  double factored_h_ = 0;
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> llt_;
  Coordinates pinned_pull_;  // h^2 sum of k x_q over springs from a free p to a pinned q, per free particle
  Coordinates y_;            // the inertial target M y = M (x0 + h v0 + h^2 g)
  Coordinates b_, X_, scratch_;
  Coordinates x0_;
  Vector bending_force_;  // the bending term's force at the step's start, when the scene has one
};

}  // namespace cloth
