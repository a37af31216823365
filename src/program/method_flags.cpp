// The method flags of the model page, parsed once for every program that takes them.
#include "program/method_flags.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/local_global.hpp"
#include "integrators/xpbd.hpp"

#include <algorithm>
#include <vector>

namespace cloth {

// [jacobian_default]
// Without --jacobian, the most exact matrix the chosen solver can take: CG needs a symmetric positive definite
// matrix, LDL^T a symmetric one (the damper's d/dx breaks symmetry in the residual form), LDU and LU take the
// exact one. An explicit incompatible choice is refused by validate(NewtonSettings) with exit status 2.
StiffnessTreatment default_treatment(LinearSolverKind solver, bool nonsymmetric) {
  if (solver == LinearSolverKind::cg) return StiffnessTreatment::definite;
  if (solver == LinearSolverKind::ldlt && nonsymmetric) return StiffnessTreatment::symmetric;
  return StiffnessTreatment::exact;
}
// [jacobian_default]

void NewtonFlags::note(const char* flag) {
  if (first_given_.empty()) first_given_ = flag;
  given_.emplace_back(flag);
}

bool NewtonFlags::given(const std::string& flag) const {
  return std::find(given_.begin(), given_.end(), flag) != given_.end();
}

void NewtonFlags::apply_defaults(const Defaults& defaults) {
  if (defaults.variant && !given("--newton")) newton_.variant = *defaults.variant;
  if (defaults.tolerance && !given("--newton-tol")) newton_.tolerance = *defaults.tolerance;
  if (defaults.line_search && !given("--line-search")) newton_.line_search = *defaults.line_search;
}

namespace {

// `--newton`'s help: each variant, with whose default it is.
std::string newton_help(NewtonVariant default_variant,
                        const std::optional<NewtonFlags::MethodDefault>& method_default) {
  const bool exception = method_default && method_default->variant != default_variant;
  const auto whose = [&](NewtonVariant v) {
    std::string w;
    if (v == default_variant) {
      w = "default";
      if (exception) w.append(" but for ").append(method_default->method);
    } else if (exception && v == method_default->variant) {
      w.append(method_default->method).append("'s default");
    }
    return w;
  };
  std::string help = "full Newton";
  if (const std::string w = whose(NewtonVariant::full); !w.empty()) help.append(" (").append(w).append(")");
  help += ", modified (a factorization kept while it converges fast, Chapter 9";
  if (const std::string w = whose(NewtonVariant::modified); !w.empty()) help.append("; ").append(w);
  help += "), or one: Baraff & Witkin's single linearised step";
  if (const std::string w = whose(NewtonVariant::one); !w.empty()) help.append(" (").append(w).append(")");
  return help;
}

}  // namespace

void NewtonFlags::add_to(CommandLine& cli, NewtonVariant default_variant,
                         const std::optional<MethodDefault>& method_default) {
  newton_.variant = default_variant;
  cli.add_value("--newton", newton_variants().accepted("|"), newton_help(default_variant, method_default),
                [this](const std::string& s) {
                  newton_.variant = newton_variants().parse(s);
                  note("--newton");
                });
  cli.add_value("--linear-solver", linear_solvers().accepted("|"),
                "block LDL^T, block LDU, block-Jacobi-preconditioned CG, Eigen's pivoting sparse LU, or automatic "
                "(the default: ldu for the exact Jacobian of a damped cloth in the residual form, ldlt otherwise)",
                [this](const std::string& s) {
                  newton_.solver = linear_solvers().parse(s);
                  note("--linear-solver");
                });
  cli.add_value("--newton-tol", "TOL", "Newton's stopping tolerance on |dv| and |r| (default 1e-8)",
                [this](const std::string& s) {
                  const double t = parse_number(s);
                  if (!(t > 0) || t >= 1) throw InputError("expected a number in (0, 1), got " + s);
                  newton_.tolerance = t;
                  note("--newton-tol");
                });
  cli.add_value("--newton-max-iter", "N",
                "Newton iterations before a step or stage fails (default " +
                    std::to_string(NewtonSettings{}.max_iterations) + ")",
                [this](const std::string& s) {
                  const long long n = parse_integer(s);
                  if (n < 1 || n > 1000) throw InputError("expected a whole number from 1 to 1000, got " + s);
                  newton_.max_iterations = static_cast<int>(n);
                  max_iterations_given_ = true;
                  note("--newton-max-iter");
                });
  cli.add_value("--line-search", line_searches().accepted("|"),
                "potential (default): full and modified Newton minimise the incremental potential, dampers frozen "
                "at the free-flight position, with backtracking on it; residual: the stage equation as it is, with "
                "backtracking on |r| (Chapter 4)",
                [this](const std::string& s) {
                  newton_.line_search = line_searches().parse(s);
                  note("--line-search");
                });
  cli.add_value("--jacobian", stiffness_treatments().accepted("|"),
                "the Newton matrix's df/dx: exact (default), symmetric (drops the damper's d/dx) or definite "
                "(compressed springs act along their axis only, after Choi & Ko 2002; the default with cg)",
                [this](const std::string& s) {
                  jacobian_ = stiffness_treatments().parse(s);
                  note("--jacobian");
                });
}

NewtonSettings NewtonFlags::settings_for(const Scene& scene) const {
  if (newton_.variant == NewtonVariant::one && max_iterations_given_ && newton_.max_iterations != 1)
    throw InputError("--newton-max-iter: --newton one takes exactly one iteration; leave --newton-max-iter out");
  NewtonSettings s = newton_;
  // The exact matrix is non-symmetric only where the damper's d/dx enters it: a damped cloth in the residual
  // form (the potential's Hessian, with the dampers frozen, is symmetric).
  s.treatment = jacobian_ ? *jacobian_ : default_treatment(s.solver, scene.has_damping() && !s.minimises());
  try {
    validate(s, scene);
  } catch (const InputError& e) {
    throw InputError(std::string("--newton ") + newton_variants().name(s.variant) + " --linear-solver " +
                     linear_solvers().name(s.solver) + " --jacobian " + stiffness_treatments().name(s.treatment) +
                     " --line-search " + line_searches().name(s.line_search) + ": " + e.what());
  }
  return s;
}

KeyValues newton_run_lines(const NewtonSettings& resolved) {
  return {{"newton", newton_variants().name(resolved.one_iteration() ? NewtonVariant::one : resolved.variant)},
          {"linear_solver", linear_solvers().name(resolved.solver)},
          {"jacobian", stiffness_treatments().name(resolved.treatment)},
          {"newton_tol", format_number(resolved.tolerance, 10)},
          {"newton_max_iter", std::to_string(resolved.max_iterations)},
          {"line_search", line_searches().name(resolved.line_search)}};
}

namespace {

// A whole number from 1 to 100000 for --iterations and --substeps.
int parse_count(const std::string& s) {
  const long long n = parse_integer(s);
  if (n < 1 || n > 100000) throw InputError("expected a whole number from 1 to 100000, got " + s);
  return static_cast<int>(n);
}

}  // namespace

void IterationFlags::add_to(CommandLine& cli) {
  cli.add_value("--iterations", "N",
                "local_global's iterations per step (default 10), or xpbd's Gauss-Seidel sweeps per substep "
                "(default 10)",
                [this](const std::string& s) { iterations_ = parse_count(s); });
  cli.add_value("--substeps", "N", "xpbd's and small_steps' substeps per step (default 1 for xpbd, 20 for small_steps)",
                [this](const std::string& s) { substeps_ = parse_count(s); });
}

void IterationFlags::apply(const Method& method, MethodSettings& settings) const {
  const bool local_global = method.name == "local_global";
  const bool xpbd = method.name == "xpbd";
  const bool position_based = method.family == MethodFamily::position_based;
  if (iterations_) {
    if (local_global) settings.local_global_iterations = *iterations_;
    else if (xpbd) settings.xpbd_iterations = *iterations_;
    else if (position_based)
      throw InputError("--iterations: " + method.name + " takes one iteration per substep by definition: use "
                       "--substeps, or --method xpbd for more iterations");
    else throw InputError("--iterations: " + method.name + " has no iterations to set: expected --method local_global "
                          "or xpbd");
  }
  if (substeps_) {
    if (!position_based)
      throw InputError("--substeps: " + method.name + " has no substeps to set: expected --method xpbd or small_steps");
    settings.substeps = *substeps_;
  }
}

KeyValues IterationFlags::run_lines(const Stepper& stepper) {
  if (const auto* lg = dynamic_cast<const LocalGlobal*>(&stepper))
    return {{"iterations", std::to_string(lg->iterations())}};
  if (const auto* xpbd = dynamic_cast<const Xpbd*>(&stepper))
    return {{"iterations", std::to_string(xpbd->iterations())}, {"substeps", std::to_string(xpbd->substeps())}};
  return {};
}

MethodSettings method_settings(const Method& method, const Scene& scene, const NewtonFlags& newton,
                               const IterationFlags& iterations) {
  MethodSettings settings;
  const std::vector<const Method*> implicit = newton_methods();
  if (std::find(implicit.begin(), implicit.end(), &method) != implicit.end())
    settings.newton = newton.settings_for(scene);
  else if (!newton.first_given().empty())
    throw InputError(newton.first_given() + ": " + method.name + " has no Newton iteration to set");
  iterations.apply(method, settings);
  return settings;
}

}  // namespace cloth
