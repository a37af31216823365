// The diagonally implicit Butcher tableaus of Chapter 9 (a_ij = 0 for j > i, the diagonal free): the built-in
// methods from their sources, an embedded pair for step control, their validation by the order conditions, and
// tableau files read in Chapter 3's format.
#pragma once

#include "integrators/butcher_tableau.hpp"

#include <string>
#include <vector>

namespace cloth {

/// A diagonally implicit Runge-Kutta method: its tableau (for an embedded pair with the second weights b^ of
/// ButcherTableau, whose combination of the same stages has another order, so that the difference of the two
/// estimates the local error), and where its coefficients come from.
struct ImplicitTableau {
  ButcherTableau method;      ///< A lower triangular, diagonal free; b_hat and embedded_order for a pair
  std::string source;         ///< where the coefficients come from (author, year)

  [[nodiscard]] bool has_embedded() const { return method.has_embedded(); }
  /// b^T is A's last row: the step's result is the last stage's value (no weights applied), which keeps the
  /// stiff decay of the last stage (Hairer & Wanner 1996, IV.6).
  [[nodiscard]] bool stiffly_accurate() const;
  /// The first stage has a_11 = 0: it is the step's starting point, explicit (an ESDIRK).
  [[nodiscard]] bool explicit_first_stage() const;
};

/// Checks that the engine of Chapter 9 can run the tableau and that it has the order it claims: square A, lower
/// triangular (nothing above the diagonal: a fully implicit tableau such as Gauss or Radau IIA couples its
/// stages in one system of s times the unknowns, which this engine does not solve), a_ii >= 0 (a negative
/// diagonal would solve a stage backward in time), c_i = sum_j a_ij, and the order conditions through the
/// claimed order, for b and for b^ (and not those of the next order: a claim below what the weights satisfy
/// would mislabel the method), b^ different from b. Throws InputError naming what fails.
void validate(const ImplicitTableau& tableau);

/// implicit_euler (backward Euler), implicit_midpoint, trapezoid, sdirk2, sdirk3, trbdf2, esdirk32, esdirk43: the
/// coefficients of the method registry's diagonally implicit rows, with their sources.
const std::vector<ImplicitTableau>& builtin_implicit_tableaus();

/// The built-in tableau called `name`; throws InputError when there is none (the method registry lists them).
const ImplicitTableau& builtin_implicit_tableau(const std::string& name);

/// Reads a diagonally implicit tableau file: Chapter 3's format (rows 'c_i a_i1 ... a_is', 'b b_1 ... b_s',
/// 'name', 'order'), and for an embedded pair the lines 'bhat bhat_1 ... bhat_s' and 'embedded_order q' (the
/// same keys Chapter 8 gives explicit pairs). Validated by validate(ImplicitTableau): the order conditions of b
/// through 'order' and of bhat through 'embedded_order'. Throws InputError naming the file, the line where one is
/// at fault, and what is wrong.
ImplicitTableau read_implicit_tableau(const std::string& path);

/// The same from text; `source` names it in messages.
ImplicitTableau parse_implicit_tableau(const std::string& text, const std::string& source);

}  // namespace cloth
