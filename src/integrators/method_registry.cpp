// The registry's rows: every method of the book, written once.
#include "integrators/method_registry.hpp"

#include "base/input_error.hpp"
#include "base/text.hpp"
#include "integrators/bdf2.hpp"
#include "integrators/explicit_runge_kutta.hpp"
#include "integrators/implicit_tableaus.hpp"
#include "integrators/local_global.hpp"
#include "integrators/symplectic_euler.hpp"

#include <cmath>
#include <sys/stat.h>

namespace cloth {

const NameTable<MethodFamily>& method_families() {
  static const NameTable<MethodFamily> table("method family",
                                             {{MethodFamily::explicit_runge_kutta, "explicit_runge_kutta"},
                                              {MethodFamily::embedded_runge_kutta, "embedded_runge_kutta"},
                                              {MethodFamily::partitioned, "partitioned"},
                                              {MethodFamily::implicit_runge_kutta, "implicit_runge_kutta"},
                                              {MethodFamily::multistep, "multistep"}});
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
Method diagonally_implicit(const char* name, const char* title, Complex (*stability)(Complex)) {
  const ImplicitTableau& t = builtin_implicit_tableau(name);
  return {name, title, MethodFamily::implicit_runge_kutta, t.method.order, t.method, stability,
          make_diagonally_implicit};
}

std::unique_ptr<Stepper> make_local_global(const Method& /*m*/, ForceField& field, const MethodSettings& settings) {
  return std::make_unique<LocalGlobal>(field, settings.local_global_iterations);
}

// A row of the explicit Runge-Kutta family: the tableau carries the method's name and order.
Method explicit_runge_kutta(const char* name, const char* title, int order,
                            std::initializer_list<std::initializer_list<double>> A, std::initializer_list<double> b,
                            Complex (*stability)(Complex)) {
  return {name, title, MethodFamily::explicit_runge_kutta, order, tableau(name, order, A, b), stability,
          make_explicit_runge_kutta};
}

}  // namespace

const std::vector<Method>& methods() {
  static const std::vector<Method> table = {
      // [explicit_euler_row]
      // Explicit Euler (Chapter 2): one stage at the start of the step, x1 = x0 + h v0, v1 = v0 + h a(x0, v0).
      explicit_runge_kutta("explicit_euler", "explicit Euler", 1, {{0}}, {1}, taylor_of_exp<1>),
      // [explicit_euler_row]
      // Symplectic Euler (Chapter 2) is a partitioned method: v1 = v0 + h a(x0, v0) is explicit Euler for v, and
      // x1 = x0 + h v1 is implicit Euler for x (tableau [1] for x, [0] for v). No single tableau describes it, so
      // it has a stepper of its own, and no scalar R(z): on a mode it acts as a 2 x 2 matrix (Chapter 7).
      {"symplectic_euler", "symplectic Euler", MethodFamily::partitioned, 1, std::nullopt, nullptr,
       make_symplectic_euler},
      // [runge_kutta_rows]
      // Chapter 3's explicit Runge-Kutta methods (Butcher 2016, Hairer, Norsett & Wanner 1993, II.1).
      explicit_runge_kutta("heun", "Heun", 2, {{0, 0}, {1, 0}}, {0.5, 0.5}, taylor_of_exp<2>),
      explicit_runge_kutta("midpoint", "explicit midpoint", 2, {{0, 0}, {0.5, 0}}, {0, 1}, taylor_of_exp<2>),
      explicit_runge_kutta("kutta3", "Kutta's third order", 3, {{0, 0, 0}, {0.5, 0, 0}, {-1, 2, 0}},
                           {1.0 / 6, 2.0 / 3, 1.0 / 6}, taylor_of_exp<3>),
      explicit_runge_kutta("rk4", "RK4", 4, {{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1, 0}},
                           {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}, taylor_of_exp<4>),
      explicit_runge_kutta("rule38", "3/8 rule", 4, {{0, 0, 0, 0}, {1.0 / 3, 0, 0, 0}, {-1.0 / 3, 1, 0, 0}, {1, -1, 1, 0}},
                           {1.0 / 8, 3.0 / 8, 3.0 / 8, 1.0 / 8}, taylor_of_exp<4>),
      // [runge_kutta_rows]
      // Implicit Euler (Chapter 4): the one-stage tableau A = [1], b = [1]. Its stepper is Chapter 4's Newton
      // solver for that one stage; NewtonSettings choose the variant (full, one), the linear solver and the
      // Jacobian treatment.
      {"implicit_euler", "implicit Euler", MethodFamily::implicit_runge_kutta, 1,
       builtin_implicit_tableau("implicit_euler").method, implicit_euler_stability_function, make_implicit_euler},
      // [implicit_rows]
      // Chapter 9's diagonally implicit methods, each stage an implicit Euler equation for StageNewton.
      diagonally_implicit("implicit_midpoint", "implicit midpoint", pade11),
      diagonally_implicit("trapezoid", "trapezoidal rule", pade11),
      diagonally_implicit("sdirk2", "SDIRK2", sdirk2_stability_function),
      diagonally_implicit("sdirk3", "SDIRK3", nullptr),
      diagonally_implicit("trbdf2", "TR-BDF2", nullptr),
      // [implicit_rows]
      // Local/global (Chapter 10; Liu, Bargteil, O'Brien & Kavan 2013): implicit Euler's step again, its equations
      // solved by a fixed number of alternating spring projections and solves with a constant matrix instead of
      // Newton's method. Converged, it is implicit Euler; with few iterations it is a method of its own, so it
      // has no tableau and no scalar R(z) here.
      {"local_global", "local/global", MethodFamily::implicit_runge_kutta, 1, std::nullopt, nullptr,
       make_local_global},
      // BDF2 (Chapter 9): a two-step method, so no tableau and no scalar R(z); its one implicit equation per step
      // is a stage equation for StageNewton (Choi & Ko 2002 use it for cloth).
      {"bdf2", "BDF2", MethodFamily::multistep, 2, std::nullopt, nullptr, make_bdf2},
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

}  // namespace cloth
