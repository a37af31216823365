// The same command gives the same cloth, to the last bit: every method run twice from scratch ends in identical
// doubles, and every chapter program run twice writes byte-identical final.dat. A figure or a table of the book
// can then be regenerated and compared, and a change in a result always means a change in the code.
#include "model/force_field.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program_runner.hpp"

#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

using namespace cloth_test;

namespace {

/// A damped run on a small cloth, from freshly built scene, forces and stepper, as a new process would.
/// The damping and the shortened last step (T = 0.205, h = 0.01) exercise every code path of the driver.
std::pair<cloth::Vector, cloth::Vector> fresh_run(const std::string& method, cloth::NewtonSettings newton) {
  cloth::SceneParams p;
  p.grid = {7, 6, 0.1};
  p.stiffness = 200;
  p.damping = 2;
  if (cloth::find_method(method).family == cloth::MethodFamily::constrained) {
    p.pins = cloth::PinSet::edge;  // the corners hold the edges straight when the springs are constraints
    p.initial_velocity_z = 0;
  }
  const cloth::Scene scene(p);
  cloth::ForceField field(scene);
  auto stepper = cloth::make_stepper(method, field, {newton});
  cloth::RunSettings rs;
  rs.dt = 0.01;
  rs.t_end = 0.205;
  const cloth::RunResult r = cloth::simulate(*stepper, rs);
  REQUIRE(r.status == cloth::RunStatus::ok);
  return {r.x, r.v};
}

void check_bit_identical(const cloth::Vector& a, const cloth::Vector& b) {
  REQUIRE(a.size() == b.size());
  int differing = 0;
  for (Eigen::Index k = 0; k < a.size(); ++k) differing += a[k] == b[k] ? 0 : 1;
  CHECK(differing == 0);
}

/// Runs `program args` twice, each in its own folder, and compares the two final.dat byte for byte.
void check_program_repeats(const std::string& program, const std::vector<std::string>& args) {
  ScratchDir scratch;
  std::string first;
  for (int run = 0; run < 2; ++run) {
    const fs::path cwd = scratch.path() / ("run" + std::to_string(run));
    fs::create_directory(cwd);
    std::vector<std::string> full = args;
    full.insert(full.end(), {"--out", "out"});
    const ProgramRun r = run_chapter(program, full, cwd);
    CAPTURE(program);
    CAPTURE(r.err);
    REQUIRE(r.status == 0);
    const std::string final_dat = read_text(cwd / "out" / "final.dat");
    REQUIRE(!final_dat.empty());
    if (run == 0) first = final_dat;
    else CHECK(final_dat == first);
  }
}

}  // namespace

TEST_CASE("every method of make_stepper, run twice from scratch, ends in bit-identical states") {
  for (const std::string& method : cloth::method_names()) {
    CAPTURE(method);
    const auto [x1, v1] = fresh_run(method, {});
    const auto [x2, v2] = fresh_run(method, {});
    check_bit_identical(x1, x2);
    check_bit_identical(v1, v2);
    CHECK(x1.allFinite());
  }
}

TEST_CASE("implicit Euler with each linear solver, run twice from scratch, ends in bit-identical states") {
  cloth::NewtonSettings cg;
  cg.solver = cloth::LinearSolverKind::cg;
  cg.treatment = cloth::StiffnessTreatment::definite;
  cloth::NewtonSettings lu;
  lu.solver = cloth::LinearSolverKind::lu;
  lu.treatment = cloth::StiffnessTreatment::exact;
  for (const cloth::NewtonSettings& s : {cloth::NewtonSettings{}, cg, lu}) {
    const std::string solver = cloth::linear_solvers().name(s.solver);
    CAPTURE(solver);
    const auto [x1, v1] = fresh_run("implicit_euler", s);
    const auto [x2, v2] = fresh_run("implicit_euler", s);
    check_bit_identical(x1, x2);
    check_bit_identical(v1, v2);
  }
}

#ifdef CLOTH_HAVE_CH02_EXPLICIT_EULER
TEST_CASE("ch02_explicit_euler run twice writes byte-identical final.dat") {
  for (const char* method : {"explicit_euler", "symplectic_euler"})
    check_program_repeats("ch02_explicit_euler",
                          {"--method", method, "--grid", "10x10", "--damping", "1", "--t-end", "0.5"});
}
#endif

#ifdef CLOTH_HAVE_CH03_RUNGE_KUTTA
TEST_CASE("ch03_runge_kutta run twice writes byte-identical final.dat, for every built-in tableau") {
  for (const cloth::Method* m : cloth::methods_of(cloth::MethodFamily::explicit_runge_kutta))
    check_program_repeats("ch03_runge_kutta",
                          {"--tableau", m->name, "--grid", "10x10", "--damping", "1", "--t-end", "0.5"});
}
#endif

#ifdef CLOTH_HAVE_CH04_IMPLICIT_EULER
TEST_CASE("ch04_implicit_euler run twice writes byte-identical final.dat, for every linear solver") {
  for (const char* solver : {"ldlt", "ldu", "cg", "lu"})
    check_program_repeats("ch04_implicit_euler", {"--linear-solver", solver, "--grid", "10x10", "--damping", "1",
                                                  "--K", "200", "--t-end", "0.5"});
  check_program_repeats("ch04_implicit_euler", {"--newton", "one", "--grid", "10x10", "--t-end", "0.5"});
}
#endif
