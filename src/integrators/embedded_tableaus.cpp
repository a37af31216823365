// Coefficients of the built-in embedded pairs, transcribed from the papers that published them and checked against
// every order condition of both rows by validate() (tests/test_tableau.cpp, tests/test_adaptive_pairs.cpp).
#include "integrators/embedded_tableaus.hpp"

#include "base/input_error.hpp"
#include "base/text.hpp"

#include <sys/stat.h>

namespace cloth {

namespace {

using Row = std::initializer_list<double>;

// A pair from its strictly lower triangle (row i holds a_i1 .. a_i,i-1; the first row is empty), b and b-hat;
// c is the row sums of A.
ButcherTableau pair(std::string name, int order, int embedded_order, std::initializer_list<Row> lower, Row b,
                    Row b_hat) {
  ButcherTableau t;
  t.name = std::move(name);
  t.order = order;
  t.embedded_order = embedded_order;
  const auto s = static_cast<Eigen::Index>(b.size());
  t.A = Eigen::MatrixXd::Zero(s, s);
  Eigen::Index i = 0;
  for (const Row& row : lower) {
    Eigen::Index j = 0;
    for (double a : row) t.A(i, j++) = a;
    ++i;
  }
  t.b = Eigen::Map<const Eigen::VectorXd>(b.begin(), s);
  t.b_hat = Eigen::Map<const Eigen::VectorXd>(b_hat.begin(), s);
  t.c = t.A.rowwise().sum();
  return t;
}

std::vector<ButcherTableau> make_pairs() {
  std::vector<ButcherTableau> pairs;
  // [embedded_pairs]
  // Heun's method with explicit Euler inside it: the simplest pair (its estimate is the Euler step's error).
  pairs.push_back(pair("heun_euler", 2, 1, {{}, {1}}, {1.0 / 2, 1.0 / 2}, {1, 0}));

  // Bogacki & Shampine (1989), "A 3(2) pair of Runge-Kutta formulas", Appl. Math. Lett. 2(4): FSAL.
  pairs.push_back(pair("bs32", 3, 2, {{}, {1.0 / 2}, {0, 3.0 / 4}, {2.0 / 9, 1.0 / 3, 4.0 / 9}},
                       {2.0 / 9, 1.0 / 3, 4.0 / 9, 0}, {7.0 / 24, 1.0 / 4, 1.0 / 3, 1.0 / 8}));

  // Fehlberg (1969), NASA TR R-315, "Low-order classical Runge-Kutta formulas with stepsize control", Table III:
  // the pair RKF4(5), which advances with its fourth-order row as Fehlberg intended.
  pairs.push_back(pair("rkf45", 4, 5,
                       {{},
                        {1.0 / 4},
                        {3.0 / 32, 9.0 / 32},
                        {1932.0 / 2197, -7200.0 / 2197, 7296.0 / 2197},
                        {439.0 / 216, -8, 3680.0 / 513, -845.0 / 4104},
                        {-8.0 / 27, 2, -3544.0 / 2565, 1859.0 / 4104, -11.0 / 40}},
                       {25.0 / 216, 0, 1408.0 / 2565, 2197.0 / 4104, -1.0 / 5, 0},
                       {16.0 / 135, 0, 6656.0 / 12825, 28561.0 / 56430, -9.0 / 50, 2.0 / 55}));

  // Cash & Karp (1990), "A variable order Runge-Kutta method for initial value problems with rapidly varying
  // right-hand sides", ACM TOMS 16(3): advanced with the fifth-order row, as Numerical Recipes and odeint do.
  pairs.push_back(pair("cash_karp", 5, 4,
                       {{},
                        {1.0 / 5},
                        {3.0 / 40, 9.0 / 40},
                        {3.0 / 10, -9.0 / 10, 6.0 / 5},
                        {-11.0 / 54, 5.0 / 2, -70.0 / 27, 35.0 / 27},
                        {1631.0 / 55296, 175.0 / 512, 575.0 / 13824, 44275.0 / 110592, 253.0 / 4096}},
                       {37.0 / 378, 0, 250.0 / 621, 125.0 / 594, 0, 512.0 / 1771},
                       {2825.0 / 27648, 0, 18575.0 / 48384, 13525.0 / 55296, 277.0 / 14336, 1.0 / 4}));

  // Dormand & Prince (1980), "A family of embedded Runge-Kutta formulae", J. Comput. Appl. Math. 6(1), the pair
  // RK5(4)7M: seven stages of which the last is the next step's first (FSAL), so six evaluations per step.
  pairs.push_back(pair("dopri5", 5, 4,
                       {{},
                        {1.0 / 5},
                        {3.0 / 40, 9.0 / 40},
                        {44.0 / 45, -56.0 / 15, 32.0 / 9},
                        {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
                        {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
                        {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}},
                       {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0},
                       {5179.0 / 57600, 0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100, 1.0 / 40}));

  // Tsitouras (2011), "Runge-Kutta pairs of order 5(4) satisfying only the first column simplifying assumption",
  // Comput. Math. Appl. 62(2), Table 1: FSAL like dopri5, with smaller fifth-order error coefficients. The paper
  // gives 16 decimals; b-hat = b - e with e the published differences (e_7 = -1/66).
  {
    const Row b = {0.09646076681806523, 0.01, 0.4798896504144996, 1.379008574103742, -3.290069515436081,
                   2.324710524099774, 0};
    const double e[] = {0.0017800110522257773, 0.0008164344596567463, -0.007880878010261994, 0.1447110071732629,
                        -0.5823571654525552,  0.45808210592918686,   -1.0 / 66};
    ButcherTableau t = pair("tsit5", 5, 4,
                            {{},
                             {0.161},
                             {-0.008480655492356989, 0.335480655492357},
                             {2.8971530571054935, -6.359448489975075, 4.3622954328695815},
                             {5.325864828439257, -11.748883564062828, 7.4955393428898365, -0.09249506636175525},
                             {5.86145544294642, -12.92096931784711, 8.159367898576159, -0.071584973281401,
                              -0.02826905039406838},
                             b},
                            b, b);
    for (Eigen::Index i = 0; i < t.b_hat.size(); ++i) t.b_hat[i] = t.b[i] - e[i];
    pairs.push_back(t);
  }
  // [embedded_pairs]
  for (const ButcherTableau& t : pairs) validate(t);
  return pairs;
}

}  // namespace

const std::vector<ButcherTableau>& embedded_tableaus() {
  static const std::vector<ButcherTableau> pairs = make_pairs();
  return pairs;
}

ButcherTableau embedded_tableau_from_argument(const std::string& name_or_path) {
  std::string names;
  for (const ButcherTableau& t : embedded_tableaus()) {
    if (t.name == name_or_path) return t;
    names += (names.empty() ? "" : ", ") + t.name;
  }
  struct stat info {};  // anything that exists is taken for a file, as in tableau_from_argument
  if (::stat(name_or_path.c_str(), &info) != 0)
    throw InputError("'" + escaped(name_or_path) + "' is neither a built-in embedded pair (" + names +
                     ") nor a readable file");
  ButcherTableau t = read_tableau(name_or_path);
  if (!t.has_embedded())
    throw InputError(escaped(name_or_path) + ": the tableau has no embedded row: an adaptive step needs a second weight row "
                     "'bhat ...' with its 'embedded_order q'");
  return t;
}

}  // namespace cloth
