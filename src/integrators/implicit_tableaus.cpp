// The diagonally implicit tableaus: built-ins from their sources, validation, and files.
#include "integrators/implicit_tableaus.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "base/text.hpp"

#include <cmath>
#include <vector>

namespace cloth {

namespace {

// Every digit of a coefficient, in the book's one number formatter.
std::string fmt(double x) { return format_number(x, 17); }

// Tableaus built from square roots and a cubic's root satisfy their conditions to a few ulps.
constexpr double tolerance = 1e-12;

ImplicitTableau make(std::string name, int order, std::initializer_list<std::initializer_list<double>> A,
                     std::initializer_list<double> b, std::string source) {
  ImplicitTableau t;
  t.method.name = std::move(name);
  t.method.order = order;
  const int s = static_cast<int>(b.size());
  t.method.A = Eigen::MatrixXd::Zero(s, s);
  int i = 0;
  for (const auto& row : A) {
    int j = 0;
    for (double a : row) t.method.A(i, j++) = a;
    ++i;
  }
  t.method.b = Eigen::Map<const Eigen::VectorXd>(b.begin(), s);
  t.method.c = t.method.A.rowwise().sum();
  t.source = std::move(source);
  return t;
}

// The order conditions of t.b through t.order, and not those of the next order (up to 4, the conditions the
// library states): a claim below what the weights satisfy would mislabel the method's measured order. `claim`
// opens the message, `key` is the file's line that states the order.
void check_order(const ButcherTableau& t, const std::string& claim, const std::string& key) {
  if (t.order < 1 || t.order > 4)
    throw InputError(claim + " " + std::to_string(t.order) + ": expected an order from 1 to 4 (the conditions "
                     "this program checks)");
  for (int p = 1; p <= t.order; ++p) {
    const double defect = order_condition_defect(t, p);
    if (defect > tolerance)
      throw InputError(claim + " " + std::to_string(t.order) + " but an order-" + std::to_string(p) +
                       " condition fails by " + fmt(defect));
  }
  int satisfied = t.order;
  while (satisfied < 4 && order_condition_defect(t, satisfied + 1) <= tolerance) ++satisfied;
  if (satisfied > t.order)
    throw InputError(claim + " " + std::to_string(t.order) + " but satisfies the order conditions through order " +
                     std::to_string(satisfied) + ": expected '" + key + " " + std::to_string(satisfied) + "'");
}

// Alexander's gamma for three stages: the root in (1/6, 1/2) of gamma^3 - 3 gamma^2 + 3/2 gamma - 1/6 = 0, which
// makes the L-stable three-stage SDIRK of order 3 (Alexander 1977; Hairer & Wanner 1996, IV.6:
// gamma = 0.4358665215). Newton's method from 0.44 reaches it to rounding in a few iterations.
double alexander_gamma3() {
  double g = 0.44;
  for (int k = 0; k < 20; ++k) g -= (((g - 3) * g + 1.5) * g - 1.0 / 6) / ((3 * g - 6) * g + 1.5);
  return g;
}

}  // namespace

bool ImplicitTableau::stiffly_accurate() const {
  const int s = method.stages();
  return method.A.row(s - 1).transpose() == method.b;
}

bool ImplicitTableau::explicit_first_stage() const { return method.A(0, 0) == 0.0; }

const std::vector<ImplicitTableau>& builtin_implicit_tableaus() {
  // [implicit_tableaus]
  static const std::vector<ImplicitTableau> tableaus = [] {
    const double r2 = std::sqrt(2.0);
    // Alexander (1977): gamma = 1 - sqrt(2)/2 makes the two-stage SDIRK L-stable and of order 2.
    const double g2 = 1 - r2 / 2;
    const double g3 = alexander_gamma3();
    const double tau = (1 + g3) / 2;
    const double b31 = -(6 * g3 * g3 - 16 * g3 + 1) / 4, b32 = (6 * g3 * g3 - 20 * g3 + 5) / 4;
    // TR-BDF2 (Bank et al. 1985) as an ESDIRK: a trapezoidal stage to t + gamma h, then BDF2 through it, with
    // gamma = 2 - sqrt(2); d = gamma / 2, w = sqrt(2) / 4 (Hosea & Shampine 1996, "Analysis and implementation
    // of TR-BDF2").
    const double d = (2 - r2) / 2, w = r2 / 4;
    std::vector<ImplicitTableau> t = {
        make("implicit_euler", 1, {{1}}, {1}, "Euler (1768); the one-stage Radau IIA method"),
        make("implicit_midpoint", 2, {{0.5}}, {1}, "the one-stage Gauss method (Hairer, Lubich & Wanner 2006)"),
        make("trapezoid", 2, {{0, 0}, {0.5, 0.5}}, {0.5, 0.5}, "Crank & Nicolson (1947) as a two-stage ESDIRK"),
        make("sdirk2", 2, {{g2, 0}, {1 - g2, g2}}, {1 - g2, g2}, "Alexander (1977), gamma = 1 - sqrt(2)/2"),
        make("sdirk3", 3, {{g3, 0, 0}, {tau - g3, g3, 0}, {b31, b32, g3}}, {b31, b32, g3},
             "Alexander (1977), gamma = 0.43586652150845899"),
        make("trbdf2", 2, {{0, 0, 0}, {d, d, 0}, {w, w, d}}, {w, w, d},
             "Bank et al. (1985); embedded pair of Hosea & Shampine (1996)"),
    };
    // TR-BDF2's third-order companion weights: the difference of the two combinations estimates the error of
    // the second-order step (Hosea & Shampine 1996).
    t.back().method.b_hat = Eigen::Vector3d((1 - w) / 3, (3 * w + 1) / 3, d / 3);
    t.back().method.embedded_order = 3;
    return t;
  }();
  // [implicit_tableaus]
  return tableaus;
}

void validate(const ImplicitTableau& tableau) {
  const ButcherTableau& t = tableau.method;
  const std::string who = "tableau '" + t.name + "': ";
  const int s = t.stages();
  if (s == 0) throw InputError(who + "has no stage");
  if (t.A.rows() != s || t.A.cols() != s || t.c.size() != s)
    throw InputError(who + "A must be " + std::to_string(s) + "x" + std::to_string(s) + " to match " +
                     std::to_string(s) + " weights b");
  if (!t.A.allFinite() || !t.b.allFinite() || !t.c.allFinite() || !t.b_hat.allFinite())
    throw InputError(who + "has a non-finite entry");
  for (int i = 0; i < s; ++i)
    for (int j = i + 1; j < s; ++j)
      if (t.A(i, j) != 0.0)
        throw InputError(who + "a_" + std::to_string(i + 1) + std::to_string(j + 1) + " = " + fmt(t.A(i, j)) +
                         " is above the diagonal: the method is fully implicit (as Gauss and Radau IIA methods "
                         "are), and this engine solves diagonally implicit methods only, one stage at a time "
                         "(a_ij = 0 for j > i)");
  for (int i = 0; i < s; ++i)
    if (t.A(i, i) < 0)
      throw InputError(who + "a_" + std::to_string(i + 1) + std::to_string(i + 1) + " = " + fmt(t.A(i, i)) +
                       " is negative: a stage would be solved backward in time; expected a_ii >= 0");
  for (int i = 0; i < s; ++i) {
    const double row_sum = t.A.row(i).sum();
    if (std::abs(t.c[i] - row_sum) > tolerance)
      throw InputError(who + "row " + std::to_string(i + 1) + ": c_" + std::to_string(i + 1) + " = " + fmt(t.c[i]) +
                       " but the row sum of A is " + fmt(row_sum) + " (consistency needs c_i = sum_j a_ij)");
  }
  // The order conditions hold for A lower triangular or not: they are the same rooted trees (Butcher 2016).
  check_order(t, who + "claims order", "order");
  if (tableau.has_embedded()) {
    if (t.b_hat.size() != s)
      throw InputError(who + "bhat has " + std::to_string(t.b_hat.size()) + " weights: expected " +
                       std::to_string(s) + ", one per stage as in b");
    if (t.b_hat == t.b) throw InputError(who + "bhat equals b: the pair would estimate every error as zero");
    ButcherTableau embedded = t;
    embedded.b = t.b_hat;
    embedded.order = t.embedded_order;
    check_order(embedded, who + "the embedded weights bhat claim order", "embedded_order");
  }
}

const ImplicitTableau& builtin_implicit_tableau(const std::string& name) {
  for (const ImplicitTableau& t : builtin_implicit_tableaus())
    if (t.method.name == name) return t;
  throw InputError("'" + escaped(name) + "' is not a built-in diagonally implicit tableau");
}

ImplicitTableau parse_implicit_tableau(const std::string& text, const std::string& source) {
  ImplicitTableau t;
  t.method = parse_tableau_entries(text, source);  // Chapter 3's format, with Chapter 8's 'bhat' and 'embedded_order'
  t.source = source;
  try {
    validate(t);
  } catch (const InputError& e) {
    throw InputError(escaped(source) + ": " + e.what());
  }
  return t;
}

ImplicitTableau read_implicit_tableau(const std::string& path) {
  return parse_implicit_tableau(read_tableau_text(path), path);
}

}  // namespace cloth
