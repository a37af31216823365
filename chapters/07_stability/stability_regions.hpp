// Chapter 7, part 1: how one step of each method acts on one mode of the linearised cloth, and the stability
// regions |R(z)| <= 1 that follow, computed from the Butcher tableaus.
#pragma once

#include "analysis/stability_function.hpp"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace ch07 {

using cloth::Complex;

/// One mode of the linearised cloth: its two eigenvalues as a first-order system (a conjugate pair, or two real
/// roots of an overdamped mode). Symplectic Euler needs the pair; the other methods act on each eigenvalue.
using Mode = std::array<Complex, 2>;

/// What linear stability theory needs of a method: R(z) as a polynomial for an explicit tableau (computed from
/// A and b), the registry's closed-form R(z) for an implicit one, or symplectic Euler's 2 x 2 step matrix.
struct StabilityModel {
  enum class Kind { polynomial, closed_form, symplectic_euler, tableau };
  std::string method;
  Kind kind = Kind::polynomial;
  std::vector<double> polynomial;                   ///< r_0..r_s of R(z) = sum r_k z^k (polynomial)
  Complex (*stability)(Complex z) = nullptr;        ///< R(z) (closed_form)
  const cloth::ButcherTableau* tableau = nullptr;   ///< R(z) = 1 + z b^T (I - zA)^-1 1 (tableau: implicit rows)
};

/// The model of a registered method (integrators/method_registry.hpp); throws cloth::InputError listing the
/// registered names for an unknown one, and for a method with neither a scalar R(z) nor a rule here.
StabilityModel stability_model(const std::string& method);

/// The largest factor by which one step of length h multiplies a mode (see the .cpp).
double growth_factor(const StabilityModel& model, double h, const std::vector<Mode>& modes);

/// How the book's prose and tables name a method: "explicit Euler", "RK4"; a method without such a name keeps its
/// registry name.
std::string method_label(const std::string& method);

/// `line` (no newline) broken at spaces into lines of at most `width` characters, the later ones indented by four
/// spaces, each ending with a newline: a transcript the book shows whole.
std::string wrapped(const std::string& line, std::size_t width = 100);

/// The methods whose regions are drawn: every explicit Runge-Kutta method, implicit Euler and symplectic Euler,
/// then the other implicit Runge-Kutta methods with a tableau (Chapter 9).
std::vector<std::string> region_methods();

/// Writes regions.dat (|R(z)| on a grid of the z-plane, one gnuplot index block per method, in the order of
/// region_methods(); Chapter 9's implicit methods on a wider grid, Re z up to 10) and prints each region's reach along the negative real and the imaginary axis; returns
/// those reaches as summary entries.
std::vector<std::pair<std::string, std::string>> stability_regions(const std::string& dir);

}  // namespace ch07
