// One composed name per method and settings (integrators/configuration.hpp): the names parse to the settings they
// say, compose back to themselves, and every malformed name is refused with a message naming the segment.
#include "base/input_error.hpp"
#include "integrators/configuration.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace cloth;

TEST_CASE("composed names parse to their settings and compose back") {
  const Configuration one = parse_configuration("implicit_euler/one/cg");
  CHECK(one.method == "implicit_euler");
  CHECK(one.settings.newton.variant == NewtonVariant::one);
  CHECK(one.settings.newton.solver == LinearSolverKind::cg);
  CHECK_FALSE(one.jacobian.has_value());

  const Configuration modified = parse_configuration("sdirk2/definite/ldlt/modified/residual");
  CHECK(modified.settings.newton.variant == NewtonVariant::modified);
  CHECK(modified.settings.newton.solver == LinearSolverKind::ldlt);
  CHECK(modified.jacobian == StiffnessTreatment::definite);
  CHECK(modified.settings.newton.line_search == LineSearch::residual);
  // Canonical order: variant, solver, Newton matrix, line search.
  CHECK(configuration_name(modified) == "sdirk2/modified/ldlt/definite/residual");

  const Configuration xpbd = parse_configuration("xpbd/4sub/16it");
  CHECK(xpbd.settings.xpbd_iterations == 16);
  CHECK(xpbd.settings.substeps == 4);
  CHECK(configuration_name(xpbd) == "xpbd/16it/4sub");
  CHECK(parse_configuration("local_global/20it").settings.local_global_iterations == 20);

  for (const std::string name : {"rk4", "symplectic_euler", "implicit_euler", "implicit_euler/one/cg",
                                 "implicit_euler/ldu/exact", "bdf2/modified", "small_steps/256sub", "xpbd/1it/64sub",
                                 "local_global/3it"}) {
    CAPTURE(name);
    CHECK(configuration_name(parse_configuration(name)) == name);
  }
}

TEST_CASE("a default spelled out is dropped from the one name") {
  CHECK(configuration_name(parse_configuration("implicit_euler/full/potential")) == "implicit_euler");
  CHECK(configuration_name(parse_configuration("local_global/10it")) == "local_global");
}

TEST_CASE("malformed composed names are refused, naming the segment") {
  const auto message = [](const std::string& name) {
    try {
      (void)parse_configuration(name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(message("rk5").find("unknown method 'rk5'") != std::string::npos);
  CHECK(message("rk4/cg").find("'cg' in 'rk4/cg'") != std::string::npos);           // explicit: no Newton
  CHECK(message("implicit_euler/qr").find("'qr'") != std::string::npos);
  CHECK(message("implicit_euler/one/full").find("twice") != std::string::npos);
  CHECK(message("implicit_euler//cg").find("empty segment") != std::string::npos);
  CHECK(message("small_steps/4it").find("only local_global and xpbd") != std::string::npos);
  CHECK(message("implicit_euler/4sub").find("only xpbd and small_steps") != std::string::npos);
  CHECK(message("xpbd/0sub").find("from 1 to 100000") != std::string::npos);
}
