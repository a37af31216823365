// What a Butcher tableau determines about its method, computed from the coefficients alone: its stages, the
// order its order conditions give, stiff accuracy, R(infinity), A- and L-stability and symplecticity. The book's
// method tables (Chapters 3 and 9) print these next to each registry row's description, so a new row is described
// by its tableau and nothing the tableau decides is typed twice.
#pragma once

#include "integrators/butcher_tableau.hpp"

namespace cloth {

/// The properties of a Runge-Kutta method that its tableau (A, b, c, b-hat) decides.
struct TableauProperties {
  int stages = 0;
  bool explicit_method = false;       ///< A strictly lower triangular: every stage from the ones before it
  bool explicit_first_stage = false;  ///< a_11 = 0 in a method that is not explicit (an ESDIRK's first stage)
  int order = 0;                      ///< the largest p (up to 8) whose order conditions b satisfies, and all below
  int embedded_order = 0;             ///< the same for b-hat; 0 when there is none
  /// b^T equals A's last row: the step's result is the last stage (Hairer & Wanner 1996, IV.6), which keeps the
  /// stiff decay of that stage.
  bool stiffly_accurate = false;
  double r_infinity = 0;  ///< R(infinity) (analysis/stability_function.hpp); infinite for an explicit method
  bool a_stable = false;  ///< |R(z)| <= 1 on the left half-plane
  bool l_stable = false;  ///< A-stable and R(infinity) = 0: a mode far stiffer than 1/h is damped out in one step
  /// b_i a_ij + b_j a_ji = b_i b_j for every i, j: the method preserves quadratic invariants and is symplectic
  /// (Hairer, Lubich & Wanner 2006, Theorem VI.4.3).
  bool symplectic = false;
};

/// The properties of `tableau`, each computed from its coefficients (conditions hold to 1e-12, as validate()
/// checks them).
TableauProperties tableau_properties(const ButcherTableau& tableau);

}  // namespace cloth
