// A method with its settings under one composed name, formed by one rule for every program, table, file and page:
// the registry's name, then each setting that differs from the registry's default as a segment after a slash
// ("rk4", "implicit_euler/one/cg", "implicit_euler/modified/ldlt/definite", "xpbd/4sub", "local_global/20it").
#pragma once

#include "integrators/method_registry.hpp"

#include <optional>
#include <string>

namespace cloth {

/// What a composed name says.
struct Configuration {
  std::string method;       ///< a registry name
  MethodSettings settings;  ///< the registry's defaults with the name's segments applied
  /// The Newton matrix when the name chose it; else a program applies its default rule for the solver
  /// (program/method_flags.hpp: default_treatment), and settings.newton.treatment is left at its default.
  std::optional<StiffnessTreatment> jacobian;
};

/// Parses "method[/segment]...". The segments, in any order, each at most once:
///   a Newton variant (full, modified, one), a linear solver (ldlt, ldu, cg, lu), a Newton matrix (exact,
///   symmetric, definite), the line search (potential, residual): only for a method Newton solves;
///   "<N>it": local_global's iterations per step or xpbd's sweeps per substep; "<N>sub": substeps of xpbd and
///   small_steps (N a whole number from 1 to 100000).
/// Throws InputError naming the segment and what is accepted.
[[nodiscard]] Configuration parse_configuration(const std::string& name);

/// The one name of `c`: the segments that differ from the registry's defaults, in the order variant, solver,
/// Newton matrix, line search, iterations, substeps. parse_configuration(configuration_name(c)) gives c back.
[[nodiscard]] std::string configuration_name(const Configuration& c);

}  // namespace cloth
