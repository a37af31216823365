// The registry's rows: every method of the book, written once.
#include "integrators/method_registry.hpp"

#include "base/input_error.hpp"
#include "base/text.hpp"
#include "integrators/bdf2.hpp"
#include "integrators/embedded_runge_kutta.hpp"
#include "integrators/explicit_runge_kutta.hpp"
#include "integrators/fast_projection.hpp"
#include "integrators/implicit_tableaus.hpp"
#include "integrators/local_global.hpp"
#include "integrators/symplectic_euler.hpp"
#include "integrators/xpbd.hpp"

#include <cmath>
#include <sys/stat.h>

namespace cloth {

const NameTable<MethodFamily>& method_families() {
  static const NameTable<MethodFamily> table("method family",
                                             {{MethodFamily::explicit_runge_kutta, "explicit_runge_kutta"},
                                              {MethodFamily::embedded_runge_kutta, "embedded_runge_kutta"},
                                              {MethodFamily::partitioned, "partitioned"},
                                              {MethodFamily::implicit_runge_kutta, "implicit_runge_kutta"},
                                              {MethodFamily::multistep, "multistep"},
                                              {MethodFamily::position_based, "position_based"},
                                              {MethodFamily::constrained, "constrained"}});
  return table;
}

namespace {

// A tableau from its rows of A and its weights b; c is the row sums of A (the consistency every tableau here has).
ButcherTableau tableau(const char* name, int order, std::initializer_list<std::initializer_list<double>> A,
                       std::initializer_list<double> b) {
  ButcherTableau t;
  t.name = name;
  t.order = order;
  const auto s = static_cast<Eigen::Index>(b.size());
  t.A = Eigen::MatrixXd::Zero(s, s);
  Eigen::Index i = 0;
  for (const auto& row : A) {
    Eigen::Index j = 0;
    for (const double a : row) t.A(i, j++) = a;
    ++i;
  }
  t.b = Eigen::Map<const Eigen::VectorXd>(b.begin(), s);
  t.c = t.A.rowwise().sum();
  return t;
}

// R(z) of an explicit method of order p with p stages: the Taylor polynomial of e^z to degree p (Hairer & Wanner
// 1996, IV.2), evaluated by Horner's rule.
template <int p>
Complex taylor_of_exp(Complex z) {
  Complex R = 1;
  for (int k = p; k >= 1; --k) R = 1.0 + z * R / static_cast<double>(k);
  return R;
}

// Implicit Euler: y1 = y0 + h lambda y1, so R(z) = 1 / (1 - z).
Complex implicit_euler_stability_function(Complex z) { return 1.0 / (1.0 - z); }

std::unique_ptr<Stepper> make_explicit_runge_kutta(const Method& m, ForceField& field,
                                                   const MethodSettings& /*settings*/) {
  return std::make_unique<ExplicitRungeKutta>(field, *m.tableau);
}

std::unique_ptr<Stepper> make_symplectic_euler(const Method& /*m*/, ForceField& field,
                                               const MethodSettings& /*settings*/) {
  return std::make_unique<SymplecticEuler>(field);
}

std::unique_ptr<Stepper> make_implicit_euler(const Method& /*m*/, ForceField& field, const MethodSettings& settings) {
  return std::make_unique<ImplicitEuler>(field, settings.newton);
}

std::unique_ptr<Stepper> make_diagonally_implicit(const Method& m, ForceField& field, const MethodSettings& settings) {
  return std::make_unique<DiagonallyImplicitRungeKutta>(field, builtin_implicit_tableau(m.name), settings.newton);
}

std::unique_ptr<Stepper> make_bdf2(const Method& /*m*/, ForceField& field, const MethodSettings& settings) {
  return std::make_unique<Bdf2>(field, settings.newton);
}

// The Pade (1,1) approximant of e^z, R(z) = (1 + z/2) / (1 - z/2): implicit midpoint's and the trapezoidal rule's.
Complex pade11(Complex z) { return (1.0 + z / 2.0) / (1.0 - z / 2.0); }

// Alexander's two-stage SDIRK, stiffly accurate: R(z) = (1 + (1 - 2 gamma) z) / (1 - gamma z)^2,
// gamma = 1 - sqrt(2)/2 (Hairer & Wanner 1996, IV.6).
Complex sdirk2_stability_function(Complex z) {
  const double g = 1 - std::sqrt(2.0) / 2;
  return (1.0 + (1 - 2 * g) * z) / ((1.0 - g * z) * (1.0 - g * z));
}

// A row of the diagonally implicit family: its coefficients and source are in implicit_tableaus.cpp.
Method diagonally_implicit(const char* name, const char* title, const char* description,
                           Complex (*stability)(Complex)) {
  const ImplicitTableau& t = builtin_implicit_tableau(name);
  return {name,      title,     description, MethodFamily::implicit_runge_kutta, t.method.order, t.method,
          stability, make_diagonally_implicit};
}

std::unique_ptr<Stepper> make_local_global(const Method& /*m*/, ForceField& field, const MethodSettings& settings) {
  return std::make_unique<LocalGlobal>(field, settings.local_global_iterations);
}

// XPBD with the iterations and substeps its settings ask for (one substep unless told).
std::unique_ptr<Stepper> make_xpbd(const Method& m, ForceField& field, const MethodSettings& settings) {
  return std::make_unique<Xpbd>(field, m.name, settings.xpbd_iterations, settings.substeps.value_or(1));
}

// Small steps: one XPBD iteration per substep, by definition, and 20 substeps per step unless told.
std::unique_ptr<Stepper> make_small_steps(const Method& m, ForceField& field, const MethodSettings& settings) {
  return std::make_unique<Xpbd>(field, m.name, 1, settings.substeps.value_or(20));
}

// The inextensible cloth's two steps (Chapter 10, integrators/fast_projection.hpp).
std::unique_ptr<Stepper> make_fast_projection(const Method& m, ForceField& field, const MethodSettings& /*settings*/) {
  return std::make_unique<ConstrainedCloth>(field, m.name, ConstrainedScheme::fast_projection);
}
std::unique_ptr<Stepper> make_rattle(const Method& m, ForceField& field, const MethodSettings& /*settings*/) {
  return std::make_unique<ConstrainedCloth>(field, m.name, ConstrainedScheme::rattle);
}

// A row of the explicit Runge-Kutta family: the tableau carries the method's name and order.
Method explicit_runge_kutta(const char* name, const char* title, const char* description, int order,
                            std::initializer_list<std::initializer_list<double>> A, std::initializer_list<double> b,
                            Complex (*stability)(Complex)) {
  return {name,  title, description, MethodFamily::explicit_runge_kutta, order, tableau(name, order, A, b),
          stability, make_explicit_runge_kutta};
}

std::unique_ptr<Stepper> make_embedded_runge_kutta(const Method& m, ForceField& field,
                                                   const MethodSettings& /*settings*/) {
  // As a Stepper the pair takes fixed steps with its row b; step control drives it through adaptive_simulate.
  return std::make_unique<EmbeddedRungeKutta>(field, *m.tableau);
}

using Row = std::initializer_list<double>;

// A row of the embedded Runge-Kutta family (Chapter 8) from its strictly lower triangle (row i holds a_i1 ..
// a_i,i-1; the first row is empty), the weights b that advance the solution and the weights b-hat that only
// measure; c is the row sums of A. `order` is the order of b, `embedded_order` that of b-hat.
Method embedded_pair(const char* name, const char* title, const char* description, int order, int embedded_order,
                     std::initializer_list<Row> lower, Row b, Row b_hat, Complex (*stability)(Complex) = nullptr) {
  ButcherTableau t;
  t.name = name;
  t.order = order;
  t.embedded_order = embedded_order;
  const auto s = static_cast<Eigen::Index>(b.size());
  t.A = Eigen::MatrixXd::Zero(s, s);
  Eigen::Index i = 0;
  for (const Row& row : lower) {
    Eigen::Index j = 0;
    for (const double a : row) t.A(i, j++) = a;
    ++i;
  }
  t.b = Eigen::Map<const Eigen::VectorXd>(b.begin(), s);
  t.b_hat = Eigen::Map<const Eigen::VectorXd>(b_hat.begin(), s);
  t.c = t.A.rowwise().sum();
  return {name,  title,     description, MethodFamily::embedded_runge_kutta, order,
          t,     stability, make_embedded_runge_kutta};
}

// Tsitouras (2011), "Runge-Kutta pairs of order 5(4) satisfying only the first column simplifying assumption",
// Comput. Math. Appl. 62(2), Table 1: first same as last like dopri5, with smaller fifth-order error coefficients.
// The paper gives 16 decimals and the differences e = b - b-hat (e_7 = -1/66), so b-hat is formed from them.
Method tsitouras5() {
  const Row b = {0.09646076681806523, 0.01, 0.4798896504144996, 1.379008574103742, -3.290069515436081,
                 2.324710524099774, 0};
  const double e[] = {0.0017800110522257773, 0.0008164344596567463, -0.007880878010261994, 0.1447110071732629,
                      -0.5823571654525552,  0.45808210592918686,   -1.0 / 66};
  Method m = embedded_pair("tsit5", "Tsitouras 5(4)",
                           "first same as last, small fifth-order error "
                           "(Tsitouras 2011)",
                           5, 4,
                           {{},
                            {0.161},
                            {-0.008480655492356989, 0.335480655492357},
                            {2.8971530571054935, -6.359448489975075, 4.3622954328695815},
                            {5.325864828439257, -11.748883564062828, 7.4955393428898365, -0.09249506636175525},
                            {5.86145544294642, -12.92096931784711, 8.159367898576159, -0.071584973281401,
                             -0.02826905039406838},
                            b},
                           b, b);
  ButcherTableau& t = *m.tableau;
  for (Eigen::Index i = 0; i < t.b_hat.size(); ++i) t.b_hat[i] = t.b[i] - e[i];
  return m;
}

}  // namespace

const std::vector<Method>& methods() {
  static const std::vector<Method> table = {
      // [explicit_euler_row]
      // Explicit Euler (Chapter 2): one stage at the start of the step, x1 = x0 + h v0, v1 = v0 + h a(x0, v0).
      explicit_runge_kutta("explicit_euler", "explicit Euler", "forward Euler, Chapter 2's method", 1,
                           {{0}}, {1}, taylor_of_exp<1>),
      // [explicit_euler_row]
      // Symplectic Euler (Chapter 2) is a partitioned method: v1 = v0 + h a(x0, v0) is explicit Euler for v, and
      // x1 = x0 + h v1 is implicit Euler for x (tableau [1] for x, [0] for v). No single tableau describes it, so
      // it has a stepper of its own, and no scalar R(z): on a mode it acts as a 2 x 2 matrix (Chapter 7).
      {"symplectic_euler", "symplectic Euler", "explicit Euler for v, then implicit Euler for x",
       MethodFamily::partitioned, 1, std::nullopt, nullptr,
       make_symplectic_euler},
      // [runge_kutta_rows]
      // Chapter 3's explicit Runge-Kutta methods (Butcher 2016, Hairer, Norsett & Wanner 1993, II.1).
      explicit_runge_kutta("heun", "Heun", "trapezoidal predictor-corrector", 2,
                           {{0, 0}, {1, 0}}, {0.5, 0.5}, taylor_of_exp<2>),
      explicit_runge_kutta("midpoint", "explicit midpoint", "the slope at the midpoint of an Euler half step", 2,
                           {{0, 0}, {0.5, 0}}, {0, 1}, taylor_of_exp<2>),
      explicit_runge_kutta("kutta3", "Kutta's third order", "Kutta's third-order method", 3,
                           {{0, 0, 0}, {0.5, 0, 0}, {-1, 2, 0}}, {1.0 / 6, 2.0 / 3, 1.0 / 6}, taylor_of_exp<3>),
      explicit_runge_kutta("rk4", "RK4", "the classic method, the report's table", 4,
                           {{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1, 0}},
                           {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}, taylor_of_exp<4>),
      explicit_runge_kutta("rule38", "3/8 rule", "Kutta's 3/8 rule", 4,
                           {{0, 0, 0, 0}, {1.0 / 3, 0, 0, 0}, {-1.0 / 3, 1, 0, 0}, {1, -1, 1, 0}},
                           {1.0 / 8, 3.0 / 8, 3.0 / 8, 1.0 / 8}, taylor_of_exp<4>),
      // [runge_kutta_rows]
      // [embedded_pairs]
      // Chapter 8's embedded pairs: two weight rows over one set of stages, b advancing the solution and b-hat
      // measuring its local error, each transcribed from the paper that published it.
      // Heun's method with explicit Euler inside it: the simplest pair (its estimate is the Euler step's error).
      embedded_pair("heun_euler", "Heun-Euler 2(1)", "Heun's method with explicit Euler inside it", 2, 1, {{}, {1}},
                    {1.0 / 2, 1.0 / 2}, {1, 0}, taylor_of_exp<2>),
      // Bogacki & Shampine (1989), "A 3(2) pair of Runge-Kutta formulas", Appl. Math. Lett. 2(4): first same as
      // last, so three evaluations per step; its b has three nonzero weights, so R(z) is Kutta's.
      embedded_pair("bs32", "Bogacki-Shampine 3(2)",
                    "first same as last (Bogacki & Shampine 1989)", 3, 2,
                    {{}, {1.0 / 2}, {0, 3.0 / 4}, {2.0 / 9, 1.0 / 3, 4.0 / 9}},
                    {2.0 / 9, 1.0 / 3, 4.0 / 9, 0}, {7.0 / 24, 1.0 / 4, 1.0 / 3, 1.0 / 8}, taylor_of_exp<3>),
      // Fehlberg (1969), NASA TR R-315, "Low-order classical Runge-Kutta formulas with stepsize control", Table
      // III: the pair RKF4(5), which advances with its fourth-order row as Fehlberg intended.
      embedded_pair("rkf45", "Fehlberg 4(5)",
                    "advances with its fourth-order row (Fehlberg 1969)", 4, 5,
                    {{},
                     {1.0 / 4},
                     {3.0 / 32, 9.0 / 32},
                     {1932.0 / 2197, -7200.0 / 2197, 7296.0 / 2197},
                     {439.0 / 216, -8, 3680.0 / 513, -845.0 / 4104},
                     {-8.0 / 27, 2, -3544.0 / 2565, 1859.0 / 4104, -11.0 / 40}},
                    {25.0 / 216, 0, 1408.0 / 2565, 2197.0 / 4104, -1.0 / 5, 0},
                    {16.0 / 135, 0, 6656.0 / 12825, 28561.0 / 56430, -9.0 / 50, 2.0 / 55}),
      // Cash & Karp (1990), "A variable order Runge-Kutta method for initial value problems with rapidly varying
      // right-hand sides", ACM TOMS 16(3): advanced with the fifth-order row, as Numerical Recipes and odeint do.
      embedded_pair("cash_karp", "Cash-Karp 5(4)",
                    "advances with its fifth-order row (Cash & Karp 1990)", 5, 4,
                    {{},
                     {1.0 / 5},
                     {3.0 / 40, 9.0 / 40},
                     {3.0 / 10, -9.0 / 10, 6.0 / 5},
                     {-11.0 / 54, 5.0 / 2, -70.0 / 27, 35.0 / 27},
                     {1631.0 / 55296, 175.0 / 512, 575.0 / 13824, 44275.0 / 110592, 253.0 / 4096}},
                    {37.0 / 378, 0, 250.0 / 621, 125.0 / 594, 0, 512.0 / 1771},
                    {2825.0 / 27648, 0, 18575.0 / 48384, 13525.0 / 55296, 277.0 / 14336, 1.0 / 4}),
      // Dormand & Prince (1980), "A family of embedded Runge-Kutta formulae", J. Comput. Appl. Math. 6(1), the pair
      // RK5(4)7M: seven stages of which the last is the next step's first (FSAL), so six evaluations per step.
      embedded_pair("dopri5", "Dormand-Prince 5(4)",
                    "first same as last (Dormand & Prince 1980)", 5, 4,
                    {{},
                     {1.0 / 5},
                     {3.0 / 40, 9.0 / 40},
                     {44.0 / 45, -56.0 / 15, 32.0 / 9},
                     {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
                     {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
                     {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}},
                    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0},
                    {5179.0 / 57600, 0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100, 1.0 / 40}),
      // Tsitouras (2011): 5(4) and first same as last; its coefficients, given to 16 digits, are written out in
      // tsitouras5(), a function of their own.
      tsitouras5(),
      // [embedded_pairs]
      // Implicit Euler (Chapter 4): the one-stage tableau A = [1], b = [1]. Its stepper is Chapter 4's Newton
      // solver for that one stage; NewtonSettings choose the variant (full, one), the linear solver and the
      // Jacobian treatment.
      {"implicit_euler", "implicit Euler", "backward Euler, Chapter 4's method", MethodFamily::implicit_runge_kutta, 1,
       builtin_implicit_tableau("implicit_euler").method, implicit_euler_stability_function, make_implicit_euler},
      // [implicit_rows]
      // Chapter 9's diagonally implicit methods, each stage an implicit Euler equation for StageNewton.
      // The description is a line of Chapter 9's table, where its citation becomes a link (method_tables.cpp).
      diagonally_implicit("implicit_midpoint", "implicit midpoint", "the one-stage Gauss method", pade11),
      diagonally_implicit("trapezoid", "trapezoidal rule", "Crank & Nicolson 1947", pade11),
      diagonally_implicit("sdirk2", "SDIRK2", "γ = 1 - √2/2 (Alexander 1977)",
                          sdirk2_stability_function),
      diagonally_implicit("sdirk3", "SDIRK3", "γ = 0.4358665215 (Alexander 1977)",
                          nullptr),
      diagonally_implicit("trbdf2", "TR-BDF2", "step control (Hosea & Shampine 1996)",
                          nullptr),
      diagonally_implicit("esdirk32", "ESDIRK3(2)4L[2]SA",
                          "stiffly accurate, L-stable, step control (Kennedy & Carpenter 2016)", nullptr),
      diagonally_implicit("esdirk43", "ESDIRK4(3)6L[2]SA",
                          "stiffly accurate, L-stable, step control (Kennedy & Carpenter 2016)", nullptr),
      // [implicit_rows]
      // Local/global (Chapter 10; Liu, Bargteil, O'Brien & Kavan 2013): implicit Euler's step again, its equations
      // solved by a fixed number of alternating spring projections and solves with a constant matrix instead of
      // Newton's method. Converged, it is implicit Euler; with few iterations it is a method of its own, so it
      // has no tableau and no scalar R(z) here.
      {"local_global", "local/global", "implicit Euler's step by spring projections and constant-matrix solves",
       MethodFamily::implicit_runge_kutta, 1, std::nullopt, nullptr,
       make_local_global},
      // BDF2 (Chapter 9): a two-step method, so no tableau and no scalar R(z); its one implicit equation per step
      // is a stage equation for StageNewton (Choi & Ko 2002 use it for cloth).
      {"bdf2", "BDF2", "the two-step backward differentiation formula", MethodFamily::multistep, 2, std::nullopt,
       nullptr, make_bdf2},
      // XPBD (Chapter 10; Macklin, Müller & Chentanez 2016): implicit Euler's step posed with one compliant
      // distance constraint per spring (compliance 1/K), solved by Gauss-Seidel projections around the inertial
      // prediction. Converged, it is implicit Euler's step up to the term its update drops (integrators/xpbd.cpp);
      // with few iterations the springs stretch more than K allows. First order, like implicit Euler.
      {"xpbd", "XPBD", "implicit Euler's step by projections of compliant spring constraints "
       "(Macklin et al. 2016)",
       MethodFamily::position_based, 1, std::nullopt, nullptr, make_xpbd},
      // Small steps (Chapter 10; Macklin et al. 2019): the same projections, one iteration per substep and many
      // substeps, which buys accuracy by shrinking the step rather than by iterating.
      {"small_steps", "small steps", "one XPBD iteration per substep, many substeps "
       "(Macklin et al. 2019)",
       MethodFamily::position_based, 1, std::nullopt, nullptr, make_small_steps},
      // The inextensible cloth (Chapter 10): structural springs and one shear diagonal per square as exact distance
      // constraints, the other springs as forces. Fast projection (Goldenthal et al. 2007) projects a symplectic
      // Euler prediction and takes v = (x_{n+1} - x_n) / h: first order. RATTLE (Andersen 1983) projects
      // positions along the step's starting gradients and velocities onto the tangent space: second order.
      {"fast_projection", "fast projection", "inextensible cloth: a symplectic Euler prediction projected onto "
       "the constraints (Goldenthal et al. 2007)", MethodFamily::constrained, 1, std::nullopt, nullptr,
       make_fast_projection},
      {"rattle", "RATTLE", "inextensible cloth: velocity Verlet with positions and velocities projected onto the "
       "constraints (Andersen 1983)", MethodFamily::constrained, 2, std::nullopt, nullptr, make_rattle},
  };
  return table;
}

const Method& find_method(const std::string& name) {
  for (const Method& m : methods())
    if (m.name == name) return m;
  std::string names;
  for (const Method& m : methods()) names += (names.empty() ? "" : ", ") + m.name;
  throw InputError("unknown method '" + name + "': expected one of " + names);
}

std::vector<const Method*> methods_of(MethodFamily family) {
  std::vector<const Method*> out;
  for (const Method& m : methods())
    if (m.family == family) out.push_back(&m);
  return out;
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const Method& m : methods()) names.push_back(m.name);
  return names;
}

std::unique_ptr<Stepper> make_stepper(const std::string& name, ForceField& field, const MethodSettings& settings) {
  return find_method(name).stepper(field, settings);
}

std::vector<const Method*> newton_methods() {
  std::vector<const Method*> out;
  for (const Method& m : methods())
    if ((m.family == MethodFamily::implicit_runge_kutta && m.tableau) || m.family == MethodFamily::multistep)
      out.push_back(&m);
  return out;
}

std::unique_ptr<NewtonStepper> make_newton_stepper(const std::string& name, ForceField& field,
                                                   const MethodSettings& settings) {
  std::string names;
  for (const Method* m : newton_methods()) {
    if (m->name == name) {
      std::unique_ptr<Stepper> stepper = m->stepper(field, settings);
      // Every such row's factory makes a NewtonStepper (the registry's test checks it), so this never fails.
      if (dynamic_cast<NewtonStepper*>(stepper.get()) != nullptr)
        return std::unique_ptr<NewtonStepper>(static_cast<NewtonStepper*>(stepper.release()));
    }
    names += (names.empty() ? "" : ", ") + m->name;
  }
  throw InputError("unknown implicit method '" + escaped(name) + "': expected one of " + names);
}

ButcherTableau tableau_from_argument(const std::string& name_or_path) {
  std::string names;
  for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta)) {
    if (m->name == name_or_path) return *m->tableau;
    names += (names.empty() ? "" : ", ") + m->name;
  }
  // Anything that exists is taken for a file, so that a folder or a FIFO is refused for what it is.
  struct stat info {};
  if (::stat(name_or_path.c_str(), &info) == 0) return read_tableau(name_or_path);
  throw InputError("'" + escaped(name_or_path) + "' is neither a built-in tableau (" + names + ") nor a readable file");
}

ButcherTableau embedded_tableau_from_argument(const std::string& name_or_path) {
  std::string names;
  for (const Method* m : methods_of(MethodFamily::embedded_runge_kutta)) {
    if (m->name == name_or_path) return *m->tableau;
    names += (names.empty() ? "" : ", ") + m->name;
  }
  struct stat info {};  // anything that exists is taken for a file, as in tableau_from_argument
  if (::stat(name_or_path.c_str(), &info) != 0)
    throw InputError("'" + escaped(name_or_path) + "' is neither a built-in embedded pair (" + names +
                     ") nor a readable file");
  ButcherTableau t = read_tableau(name_or_path);
  if (!t.has_embedded())
    throw InputError(escaped(name_or_path) + ": the tableau has no embedded row: an adaptive step needs a second "
                     "weight row 'bhat ...' with its 'embedded_order q'");
  return t;
}

}  // namespace cloth
