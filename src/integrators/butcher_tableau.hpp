// The Butcher tableau (A, b, c) of a Runge-Kutta method, its validation against the order conditions, and the
// small text format a reader can write a tableau in. The book's own tableaus are rows of the method registry.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cloth {

/// An s-stage Runge-Kutta method: stage i evaluates at t + c_i h the state y + h sum_j a_ij k_j, and the step
/// is y + h sum_i b_i k_i (Butcher 2016, Hairer, Norsett & Wanner 1993, II.1).
struct ButcherTableau {
  std::string name;
  int order = 1;      ///< the order the tableau claims; validate() checks the conditions up to it
  Eigen::MatrixXd A;  ///< s x s
  Eigen::VectorXd b;  ///< weights, s
  Eigen::VectorXd c;  ///< nodes, s

  [[nodiscard]] int stages() const { return static_cast<int>(b.size()); }
};

/// Checks that the tableau is one the explicit engine runs and that it has the order it claims:
/// square A, strictly lower triangular (explicit), c_i = sum_j a_ij, and the order conditions through the claimed
/// order (1 to 4) to rounding, but not those of the next order (a claim lower than the tableau's order, up to 4,
/// is refused too). Throws InputError naming the first row or condition that fails.
void validate(const ButcherTableau& tableau);

/// The largest |residual| of the order conditions of order p (p = 1..4); 0 for a method of order >= p.
double order_condition_defect(const ButcherTableau& tableau, int p);

/// Reads the text format of Chapter 3 (see chapters/03_runge_kutta/rk4_report.tableau) from a regular file of
/// printable text and at most 64 KiB (base/text_file.hpp). Throws InputError naming the file and what is wrong:
/// not a regular file, too large, a byte that is not text, a line of the format, a key ('name', 'order') given
/// twice, or an order claim the conditions contradict.
ButcherTableau read_tableau(const std::string& path);

/// Parses that format from text; `source` names it in error messages (escaped). The name the text gives is any
/// word: a program that makes a file name of it reduces it with safe_file_name (base/text.hpp) first.
ButcherTableau parse_tableau(const std::string& text, const std::string& source);

/// The same format read without validate(): the shapes are checked, the method is not. For engines that accept
/// other tableaus than the explicit engine (Chapter 9's diagonally implicit ones), which validate them their way.
ButcherTableau parse_tableau_entries(const std::string& text, const std::string& source);

/// One entry of the format: a finite decimal or a fraction p/q. False when `token` is neither.
bool parse_tableau_entry(const std::string& token, double& value);

/// The whole text of a tableau file; throws InputError when it cannot be read.
std::string read_tableau_text(const std::string& path);

}  // namespace cloth
