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

// Kennedy & Carpenter's ESDIRK3(2)4L[2]SA (2016 review, section 5.1.2): four stages, the first explicit, c_2 =
// 2 gamma (stage 2 is a trapezoidal step), c_3 = 3/5, stiffly accurate, order 3, and gamma = 0.4358665215...
// the same root as Alexander's, the one that makes R(infinity) = 0. With gamma and c_3 chosen, the four
// third-order conditions on b = (a_41, a_42, a_43, gamma) fix b_1, b_2, b_3 and a_32:
//   b_2 c_2 + b_3 c_3 = 1/2 - gamma,  b_2 c_2^2 + b_3 c_3^2 = 1/3 - gamma          (b c = 1/2, b c^2 = 1/3)
//   b_2 (2 gamma^2) + b_3 (a_32 c_2 + gamma c_3) + gamma / 2 = 1/6                 (b A c = 1/6)
//   b_1 = 1 - gamma - b_2 - b_3,  a_31 = c_3 - gamma - a_32.
// The embedded weights are the review's (second order, chosen there for their stability and error properties),
// to 17 significant digits.
ImplicitTableau esdirk32() {
  const double g = alexander_gamma3(), c2 = 2 * g, c3 = 0.6;
  const double r1 = 0.5 - g, r2 = 1.0 / 3 - g;
  const double det = c2 * c3 * c3 - c3 * c2 * c2;
  const double b2 = (r1 * c3 * c3 - r2 * c3) / det, b3 = (c2 * r2 - c2 * c2 * r1) / det;
  const double b1 = 1 - g - b2 - b3;
  const double a32 = ((1.0 / 6 - g / 2 - 2 * g * g * b2) / b3 - g * c3) / c2, a31 = c3 - g - a32;
  ImplicitTableau t = make("esdirk32", 3, {{0, 0, 0, 0}, {g, g, 0, 0}, {a31, a32, g, 0}, {b1, b2, b3, g}},
                           {b1, b2, b3, g}, "Kennedy & Carpenter (2016), ESDIRK3(2)4L[2]SA");
  t.method.b_hat = Eigen::Vector4d(0.10889661761586122, -0.91532581187071183, 1.2712735973021543,
                                   0.53515559695269621);
  t.method.embedded_order = 2;
  return t;
}

// Kennedy & Carpenter's ESDIRK4(3)6L[2]SA (2016 review, Table 16): six stages, the first explicit, gamma = 1/4,
// c = (0, 1/2, (2 - sqrt 2)/4, 5/8, 26/25, 1), stiffly accurate, order 4, L-stable; the coefficients in the
// closed forms of the review, each row's first entry from c_i = sum_j a_ij (a_i1 = a_i2 in every row). The
// embedded weights (order 3) are the review's rationals.
ImplicitTableau esdirk43() {
  const double r2 = std::sqrt(2.0), g = 0.25;
  const double c3 = (2 - r2) / 4, c4 = 5.0 / 8, c5 = 26.0 / 25;
  const double a32 = (1 - r2) / 8, a31 = c3 - a32 - g;
  const double a42 = (5 - 7 * r2) / 64, a43 = 7 * (1 + r2) / 32, a41 = c4 - a42 - a43 - g;
  const double a52 = (-13796 - 54539 * r2) / 125000, a53 = (506605 + 132109 * r2) / 437500;
  const double a54 = 166 * (-97 + 376 * r2) / 109375, a51 = c5 - a52 - a53 - a54 - g;
  const double b2 = (1181 - 987 * r2) / 13782, b3 = 47 * (-267 + 1783 * r2) / 273343;
  const double b4 = -16 * (-22922 + 3525 * r2) / 571953, b5 = -15625 * (97 + 376 * r2) / 90749876;
  const double b1 = 1 - b2 - b3 - b4 - b5 - g;
  ImplicitTableau t = make("esdirk43", 4,
                           {{0, 0, 0, 0, 0, 0},
                            {g, g, 0, 0, 0, 0},
                            {a31, a32, g, 0, 0, 0},
                            {a41, a42, a43, g, 0, 0},
                            {a51, a52, a53, a54, g, 0},
                            {b1, b2, b3, b4, b5, g}},
                           {b1, b2, b3, b4, b5, g}, "Kennedy & Carpenter (2016), ESDIRK4(3)6L[2]SA");
  const double h2 = -480923228411.0 / 4982971448372, h3 = 6709447293961.0 / 12833189095359;
  const double h4 = 3513175791894.0 / 6748737351361, h5 = -498863281070.0 / 6042575550617;
  const double h6 = 2077005547802.0 / 8945017530137;
  t.method.b_hat.resize(6);
  t.method.b_hat << 1 - h2 - h3 - h4 - h5 - h6, h2, h3, h4, h5, h6;
  t.method.embedded_order = 3;
  return t;
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
    // Kennedy & Carpenter's stiffly accurate, L-stable ESDIRK pairs, for step control at third and fourth order.
    t.push_back(esdirk32());
    t.push_back(esdirk43());
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
