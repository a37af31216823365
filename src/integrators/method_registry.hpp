// The book's time integrators, each named once, in one table in the spirit of SUNDIALS ARKODE's catalogue of
// Butcher tables: its name, its title for legends, its family, its tableau, its order, its stability function,
// the factory that makes its Stepper, and a line describing it for the book's tables. Every program, test and chapter takes its methods from here; a chapter that
// brings a new method adds a row.
#pragma once

#include "base/name_table.hpp"
#include "integrators/butcher_tableau.hpp"
#include "integrators/implicit_euler.hpp"
#include "integrators/implicit_tableaus.hpp"
#include "integrators/newton_stepper.hpp"
#include "integrators/stepper.hpp"

#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cloth {

using Complex = std::complex<double>;

/// What kind of method a row is, which says how its tableau (if any) is to be read and run.
enum class MethodFamily {
  explicit_runge_kutta,  ///< a strictly lower triangular tableau, run by the one ExplicitRungeKutta engine
  embedded_runge_kutta,  ///< an explicit tableau with a second weight row b-hat that estimates the local error
  partitioned,           ///< different rules for x and for v, so no single tableau (symplectic Euler)
  implicit_runge_kutta,  ///< a tableau with entries on or above the diagonal: stages solved by Newton's method
  multistep,             ///< a step that uses earlier steps as well as the current state
  position_based,        ///< springs as compliant constraints projected around an inertial prediction (XPBD)
  constrained,           ///< stiff springs as exact distance constraints, the rest as forces (Chapter 10)
};
/// The families by name: explicit_runge_kutta, embedded_runge_kutta, partitioned, implicit_runge_kutta, multistep,
/// position_based, constrained.
const NameTable<MethodFamily>& method_families();

/// The settings a method's factory may read. Explicit methods read none; implicit ones read Newton's.
struct MethodSettings {
  NewtonSettings newton;
  int local_global_iterations = 10;  ///< local/global iterations per step (Chapter 10; Liu et al. 2013 use ~10)
  int xpbd_iterations = 10;  ///< `xpbd`'s Gauss-Seidel sweeps per substep (`small_steps` takes one, by definition)
  /// Substeps per step of the position-based rows; unset, each row's own: 1 for `xpbd`, 20 for `small_steps`.
  std::optional<int> substeps = std::nullopt;
};

/// One row of the registry.
struct Method {
  std::string name;     ///< what programs, files and run.txt call it: "rk4"
  std::string title;    ///< what legends and tables print: "RK4"
  /// One line for the book's method tables (Doxygen Markdown; a citation links to the references page). What
  /// the tableau determines (stages, order, stiff accuracy, R(infinity), stability) is computed, never written
  /// here: analysis/tableau_properties.hpp.
  std::string description;
  MethodFamily family;
  int order;            ///< the order it claims; tests check it against its tableau and against measurement
  /// Its Butcher tableau (A, b, c), with the same name and order, where the method has one.
  std::optional<ButcherTableau> tableau;
  /// Its stability function R(z) in closed form (one step of y' = lambda y multiplies y by R(h lambda)), where
  /// the method has a scalar one; tests compare it with the R(z) computed from the tableau.
  Complex (*stability)(Complex z) = nullptr;
  /// Makes the method's stepper on `field`.
  std::unique_ptr<Stepper> (*make)(const Method& method, ForceField& field, const MethodSettings& settings) = nullptr;

  [[nodiscard]] std::unique_ptr<Stepper> stepper(ForceField& field, const MethodSettings& settings = {}) const {
    return make(*this, field, settings);
  }
};

/// Every registered method, in the book's order (the order of legends and tables).
const std::vector<Method>& methods();

/// The method called `name`. Throws InputError "unknown method 'x': expected one of ..." listing every name.
const Method& find_method(const std::string& name);

/// The methods of one family, in registry order.
std::vector<const Method*> methods_of(MethodFamily family);

/// Every registered name, in registry order.
std::vector<std::string> method_names();

/// find_method(name).stepper(field, settings).
std::unique_ptr<Stepper> make_stepper(const std::string& name, ForceField& field, const MethodSettings& settings = {});

/// The methods whose implicit equations StageNewton solves: the diagonally implicit rows (implicit_runge_kutta
/// with a tableau) and the multistep ones, in registry order.
std::vector<const Method*> newton_methods();

/// One of newton_methods() by name, as the NewtonStepper it is (its settings, residuals and timing readable).
/// Throws InputError "unknown implicit method 'x': expected one of ..." listing their names.
std::unique_ptr<NewtonStepper> make_newton_stepper(const std::string& name, ForceField& field,
                                                   const MethodSettings& settings = {});

/// The tableau of a registered explicit Runge-Kutta method, or else a tableau file by path (Chapter 3's format).
/// Throws InputError listing the accepted names when neither exists, or naming the line that is wrong in a file.
ButcherTableau tableau_from_argument(const std::string& name_or_path);

/// The tableau of a registered embedded pair (Chapter 8), or else a tableau file with a 'bhat' row. Throws
/// InputError listing the pairs' names when neither exists, naming the line that is wrong in a file, or when the
/// file's tableau has no embedded row.
ButcherTableau embedded_tableau_from_argument(const std::string& name_or_path);

}  // namespace cloth
