// The Butcher tableau (A, b, c) of a Runge-Kutta method, with an optional second weight row b-hat for an
// embedded pair (Chapter 8), its validation against the order conditions, and the small text format a reader can
// write a tableau in. The book's own tableaus are rows of the method registry.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cloth {

/// An s-stage Runge-Kutta method: stage i evaluates at t + c_i h the state y + h sum_j a_ij k_j, and the step
/// is y + h sum_i b_i k_i (Butcher 2016, Hairer, Norsett & Wanner 1993, II.1).
/// An embedded pair carries a second weight row b-hat over the same stages: y + h sum_i bhat_i k_i is a second
/// solution of another order, and the difference of the two estimates the local error (Chapter 8). The row b
/// always advances the solution; b-hat only measures. Dormand-Prince 5(4) therefore has its fifth-order row as b
/// (local extrapolation), Fehlberg 4(5) its fourth-order row, as both were published.
struct ButcherTableau {
  std::string name;
  int order = 1;           ///< the order of b, as claimed; validate() checks the conditions up to it
  Eigen::MatrixXd A;       ///< s x s
  Eigen::VectorXd b;       ///< weights that advance the solution, s
  Eigen::VectorXd c;       ///< nodes, s
  Eigen::VectorXd b_hat;   ///< embedded weights, s; empty when the method is not a pair
  int embedded_order = 0;  ///< the order of b_hat, as claimed (0 when there is none)

  [[nodiscard]] int stages() const { return static_cast<int>(b.size()); }
  [[nodiscard]] bool has_embedded() const { return b_hat.size() > 0; }
  /// First same as last: the last stage is evaluated at the new state itself (its row of A is b and b_s = 0), so
  /// an accepted step's last stage is the next step's first and costs nothing (Dormand & Prince 1980).
  [[nodiscard]] bool first_same_as_last() const;
};

/// Checks that the tableau is one the explicit engine runs and that it has the order it claims:
/// square A, strictly lower triangular (explicit), c_i = sum_j a_ij, and the order conditions through the claimed
/// order (1 to 8, generated from the rooted trees: order_conditions.hpp) to rounding, for b and for b-hat, but not
/// those of the next order (a claim lower than the row's order is refused too). Throws InputError naming the
/// first row or condition that fails.
void validate(const ButcherTableau& tableau);

/// The largest |residual| of the order conditions of order p (1 to 8) for b, or for b-hat when `embedded`;
/// 0 (to rounding) for a row of order >= p.
double order_condition_defect(const ButcherTableau& tableau, int p, bool embedded = false);

/// Reads the text format of Chapter 3 (see chapters/03_runge_kutta/rk4_report.tableau), with the optional
/// embedded row of Chapter 8 ('bhat ...' and 'embedded_order q'; chapters/08_adaptive_step/dopri5.tableau), from
/// a regular file of printable text and at most 64 KiB (base/text_file.hpp). Throws InputError naming the file and
/// what is wrong: not a regular file, too large, a byte that is not text, a line of the format, a key ('name',
/// 'order', 'embedded_order') given twice, or an order claim the conditions contradict.
ButcherTableau read_tableau(const std::string& path);

/// Parses that format from text; `source` names it in error messages (escaped). The name the text gives is any
/// word: a program that makes a file name of it reduces it with safe_file_name (base/text.hpp) first.
ButcherTableau parse_tableau(const std::string& text, const std::string& source);

/// The same format read without validate(): the shapes are checked, the method is not. For engines that accept
/// other tableaus than the explicit engine (Chapter 9's diagonally implicit ones), which validate them their way.
ButcherTableau parse_tableau_entries(const std::string& text, const std::string& source);

/// One entry of the format: a number (base/parse_number.hpp: decimal or hexadecimal, finite, normal) or a fraction
/// p/q of two, whose value must be one too. Throws InputError saying what is wrong otherwise.
double parse_tableau_entry(const std::string& token);

/// The whole text of a tableau file; throws InputError when it cannot be read.
std::string read_tableau_text(const std::string& path);

}  // namespace cloth
