// The one rule that names a method with its settings (configuration.hpp): parsing a composed name segment by
// segment against the registry's tables, and composing the canonical name back.
#include "integrators/configuration.hpp"

#include "base/input_error.hpp"
#include "base/parse_number.hpp"

#include <algorithm>
#include <vector>

namespace cloth {

namespace {

bool solved_by_newton(const std::string& method) {
  const std::vector<const Method*> newton = newton_methods();
  return std::any_of(newton.begin(), newton.end(), [&](const Method* m) { return m->name == method; });
}

// "<N><suffix>" with N a whole number from 1 to 100000, or nothing when `segment` does not end in `suffix`.
std::optional<int> count_segment(const std::string& segment, const std::string& suffix) {
  if (segment.size() <= suffix.size() || segment.compare(segment.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  const std::string digits = segment.substr(0, segment.size() - suffix.size());
  if (!std::all_of(digits.begin(), digits.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
    return std::nullopt;
  const long long n = parse_integer(digits);
  if (n < 1 || n > 100000) throw InputError("'" + segment + "': expected a count from 1 to 100000");
  return static_cast<int>(n);
}

struct Given {
  bool variant = false, solver = false, line_search = false, iterations = false, substeps = false;
};

void once(bool& given, const std::string& segment, const std::string& name) {
  if (given) throw InputError("'" + name + "' sets the same setting twice (at '" + segment + "')");
  given = true;
}

void apply_newton_segment(const std::string& segment, const std::string& name, Configuration& c, Given& given) {
  NewtonSettings& n = c.settings.newton;
  if (const auto v = newton_variants().find(segment)) {
    once(given.variant, segment, name);
    n.variant = *v;
  } else if (const auto s = linear_solvers().find(segment); s && *s != LinearSolverKind::automatic) {
    once(given.solver, segment, name);
    n.solver = *s;
  } else if (const auto t = stiffness_treatments().find(segment)) {
    if (c.jacobian) throw InputError("'" + name + "' sets the same setting twice (at '" + segment + "')");
    c.jacobian = *t;
    n.treatment = *t;
  } else if (const auto l = line_searches().find(segment)) {
    once(given.line_search, segment, name);
    n.line_search = *l;
  } else {
    throw InputError("'" + segment + "' in '" + name + "': expected a Newton variant (" + newton_variants().accepted() +
                     "), a linear solver (ldlt, ldu, cg, lu), a Newton matrix (" + stiffness_treatments().accepted() +
                     ") or a line search (" + line_searches().accepted() + ")");
  }
}

void apply_iteration_segment(const std::string& segment, const std::string& name, Configuration& c, Given& given) {
  const Method& m = find_method(c.method);
  if (const auto it = count_segment(segment, "it")) {
    once(given.iterations, segment, name);
    if (m.name == "local_global") c.settings.local_global_iterations = *it;
    else if (m.name == "xpbd") c.settings.xpbd_iterations = *it;
    else throw InputError("'" + segment + "' in '" + name + "': only local_global and xpbd take iterations");
  } else if (const auto sub = count_segment(segment, "sub")) {
    once(given.substeps, segment, name);
    if (m.family != MethodFamily::position_based)
      throw InputError("'" + segment + "' in '" + name + "': only xpbd and small_steps take substeps");
    c.settings.substeps = *sub;
  } else {
    throw InputError("'" + segment + "' in '" + name + "': " + m.name +
                     " takes no such setting (accepted: <N>it, <N>sub, and for an implicit method its Newton settings)");
  }
}

}  // namespace

Configuration parse_configuration(const std::string& name) {
  Configuration c;
  std::size_t start = name.find('/');
  c.method = find_method(name.substr(0, start)).name;  // throws "unknown method ..." with every name
  const bool newton = solved_by_newton(c.method);
  Given given;
  while (start != std::string::npos) {
    const std::size_t end = name.find('/', start + 1);
    const std::string segment = name.substr(start + 1, end == std::string::npos ? std::string::npos : end - start - 1);
    if (segment.empty()) throw InputError("'" + name + "': an empty segment between slashes");
    if (newton && !count_segment(segment, "it") && !count_segment(segment, "sub"))
      apply_newton_segment(segment, name, c, given);
    else
      apply_iteration_segment(segment, name, c, given);
    start = end;
  }
  return c;
}

std::string configuration_name(const Configuration& c) {
  const MethodSettings defaults;
  const NewtonSettings& n = c.settings.newton;
  std::string out = find_method(c.method).name;
  const auto segment = [&out](const std::string& text) {
    out.push_back('/');
    out.append(text);
  };
  if (solved_by_newton(c.method)) {
    const NewtonVariant variant = n.one_iteration() ? NewtonVariant::one : n.variant;
    if (variant != defaults.newton.variant) segment(newton_variants().name(variant));
    if (n.solver != LinearSolverKind::automatic) segment(linear_solvers().name(n.solver));
    if (c.jacobian) segment(stiffness_treatments().name(*c.jacobian));
    if (n.line_search != defaults.newton.line_search) segment(line_searches().name(n.line_search));
  }
  if (c.method == "local_global" && c.settings.local_global_iterations != defaults.local_global_iterations)
    segment(std::to_string(c.settings.local_global_iterations).append("it"));
  if (c.method == "xpbd" && c.settings.xpbd_iterations != defaults.xpbd_iterations)
    segment(std::to_string(c.settings.xpbd_iterations).append("it"));
  if (c.settings.substeps) segment(std::to_string(*c.settings.substeps).append("sub"));
  return out;
}

}  // namespace cloth
