// BDF2 on the cloth (Chapter 9): the two-step backward differentiation formula, whose one implicit equation per
// step is again a stage equation for StageNewton. Choi & Ko (2002) and Bridson, Marino & Fedkiw (2003) use it for
// cloth.
#pragma once

#include "integrators/newton_stepper.hpp"

#include <string>

namespace cloth {

/// With constant h, BDF2 is y_{n+1} = 4/3 y_n - 1/3 y_{n-1} + 2/3 h y'_{n+1}; on x' = v, M v' = f it reads
///   x_{n+1} = x~ + gamma v_{n+1},  M (v_{n+1} - v~) = gamma f(x_{n+1}, v_{n+1}),
///   x~ = 4/3 x_n - 1/3 x_{n-1},  v~ = 4/3 v_n - 1/3 v_{n-1},  gamma = 2/3 h,
/// the implicit Euler equation from (x~, v~) with gamma for h. A multistep method needs a past: the first step,
/// and any step after the state or h changed under it, is one backward Euler step (its local error O(h^2) costs
/// the second order nothing globally).
class Bdf2 final : public NewtonStepper {
 public:
  Bdf2(ForceField& field, NewtonSettings settings);
  [[nodiscard]] std::string name() const override;
  bool step(double h, Vector& x, Vector& v) override;

 private:
  Vector x_previous_, v_previous_;  // y_{n-1}
  Vector x_last_, v_last_;          // y_n as this stepper left it, to notice a state it did not produce
  Vector x_tilde_, v_tilde_, V_;
  double h_last_ = 0;
  bool have_history_ = false;
};

}  // namespace cloth
