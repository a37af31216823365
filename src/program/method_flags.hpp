// The method flags of the model page parsed in one place: Newton's (--newton, --linear-solver, --jacobian,
// --newton-tol, --newton-max-iter, --line-search) for every program that runs an implicit method, with the one default rule for
// the Newton matrix, and the iterative methods' (--iterations, --substeps) for local/global and XPBD.
#pragma once

#include "integrators/method_registry.hpp"
#include "program/command_line.hpp"
#include "program/run_outputs.hpp"

#include <optional>
#include <string>
#include <vector>

namespace cloth {

/// Without `--jacobian`, the most exact Newton matrix the chosen solver can take: CG needs a symmetric positive
/// definite matrix (definite), LDL^T a symmetric one (symmetric, when the damper's d/dx would break symmetry:
/// `nonsymmetric` is true for a damped cloth in the residual form), LDU
/// and LU take the exact one. An explicit incompatible choice is refused by NewtonFlags::settings_for.
StiffnessTreatment default_treatment(LinearSolverKind solver, bool nonsymmetric);

/// Newton's six flags. Usage:
///   NewtonFlags newton;
///   newton.add_to(cli);                                          // before cli.parse
///   const NewtonSettings s = newton.settings_for(Scene(params));  // after it: the default rule, validated
class NewtonFlags {
 public:
  /// A method whose variant without `--newton` is not the program's, which the program applies itself (Chapter
  /// 11's implicit_euler takes Baraff and Witkin's single iteration): named in `--newton`'s help.
  struct MethodDefault {
    std::string method;
    NewtonVariant variant;
  };
  /// Adds `--newton`, `--linear-solver`, `--newton-tol`, `--newton-max-iter`, `--line-search` and `--jacobian`
  /// to `cli`; without `--newton` the program runs `default_variant` (Chapter 9's fixed steps: modified), and
  /// `--help` says so, with `method_default`'s exception when it is given.
  void add_to(CommandLine& cli, NewtonVariant default_variant = NewtonVariant::full,
              const std::optional<MethodDefault>& method_default = std::nullopt);

  /// The settings the flags chose, the Newton matrix's treatment by default_treatment() unless `--jacobian` chose
  /// it. Throws InputError naming the flags when they contradict each other (`--newton one` with another
  /// `--newton-max-iter`) or the solver cannot take the matrix.
  [[nodiscard]] NewtonSettings settings_for(const Scene& scene) const;

  /// The settings as given, before the default rule: the treatment is the one `--jacobian` chose, or exact.
  [[nodiscard]] const NewtonSettings& given() const { return newton_; }
  /// The treatment `--jacobian` chose, if it was given.
  [[nodiscard]] const std::optional<StiffnessTreatment>& jacobian() const { return jacobian_; }
  /// The first of the six flags given on the command line, or empty: a program refuses it for a method that
  /// has no Newton iteration.
  [[nodiscard]] const std::string& first_given() const { return first_given_; }
  /// Whether `flag` (one of the six) was given on the command line.
  [[nodiscard]] bool given(const std::string& flag) const;

  /// A program's own defaults for some of the flags, each applied only when its flag was not given (after
  /// cli.parse, before settings_for): Chapter 9's controlled runs take modified Newton, the residual form and a
  /// Newton tolerance tied to the error tolerance.
  struct Defaults {
    std::optional<NewtonVariant> variant;
    std::optional<double> tolerance;
    std::optional<LineSearch> line_search;
  };
  void apply_defaults(const Defaults& defaults);

 private:
  void note(const char* flag);
  NewtonSettings newton_;
  std::optional<StiffnessTreatment> jacobian_;
  bool max_iterations_given_ = false;
  std::string first_given_;
  std::vector<std::string> given_;
};

/// run.txt's lines for Newton's settings (resolved: the solver the automatic choice picked): newton,
/// linear_solver, jacobian, newton_tol, newton_max_iter, line_search.
KeyValues newton_run_lines(const NewtonSettings& resolved);

/// `--iterations` and `--substeps`, the settings of the registry's iterative rows: local/global's iterations per
/// step, XPBD's iterations per substep, and the substeps of XPBD and small steps. A method that does not read a
/// flag refuses it (settings_for), so a flag never silently does nothing.
class IterationFlags {
 public:
  void add_to(CommandLine& cli);
  /// `settings` with the flags given applied for `method`. Throws InputError naming the flag when `method` has no
  /// such setting (small steps take one iteration per substep by definition).
  void apply(const Method& method, MethodSettings& settings) const;
  /// run.txt's lines for the iterations and substeps `stepper` takes (none for a method without them).
  static KeyValues run_lines(const Stepper& stepper);

 private:
  std::optional<int> iterations_;
  std::optional<int> substeps_;
};

/// The settings of `method` from both kinds of flags: Newton's for the methods StageNewton solves (by
/// NewtonFlags::settings_for), the iterations and substeps for the iterative rows (IterationFlags::apply). Throws
/// InputError naming the first Newton flag given for a method that has no Newton iteration, and whatever the two
/// calls throw. What `ch10_cloth` and the book's WebAssembly module (web/cloth_web.cpp) run a method with.
MethodSettings method_settings(const Method& method, const Scene& scene, const NewtonFlags& newton,
                               const IterationFlags& iterations);

}  // namespace cloth
