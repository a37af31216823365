// Bad input, end to end: every chapter program is run with what a reader might mistype, and must answer with exit
// status 2, one line on stderr naming the flag (or the file) and what is accepted, and nothing written.
// The parser itself is also checked in-process, where the sanitizer build sees every byte it touches.
#include "program/command_line.hpp"
#include "base/input_error.hpp"
#include "integrators/butcher_tableau.hpp"
#include "integrators/method_registry.hpp"
#include "program_runner.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cloth_test;

namespace {

/// One bad command line and the pieces its error line must contain. "@S" in an argument stands for the scratch
/// folder, which holds a regular file `a_file` and the tableau files below, outside the program's working folder.
struct BadInput {
  std::vector<std::string> args;
  std::vector<std::string> expect;
};

// Tableau files a reader could get wrong, in the format of Chapter 3 (rows `c_i a_i1 .. a_is`, then `b ...`).
void write_tableau_files(const fs::path& dir) {
  const auto write = [&](const char* name, const char* text) { std::ofstream(dir / name) << text; };
  write("a_file", "not a folder\n");
  write("empty.tableau", "");
  write("ragged.tableau", "order 2\n0 0 0\n1 1\nb 1/2 1/2\n");
  write("word.tableau", "order 2\n0 0 0\n1 one 0\nb 1/2 1/2\n");
  write("implicit.tableau", "order 1\n1 1\nb 1\n");
  write("inconsistent.tableau", "order 2\n0 0 0\n0.5 1 0\nb 1/2 1/2\n");
  // The two-stage Gauss method (order 4), fully implicit: Chapter 9's engine refuses it.
  write("gauss2.tableau", "order 4\n0.21132486540518713 0.25 -0.038675134594812866\n"
                          "0.78867513459481287 0.53867513459481287 0.25\nb 1/2 1/2\n");
  // The trapezoidal rule with explicit Euler's weights embedded (orders 2 and 1), and the same claiming too much.
  write("trapezoid_pair.tableau", "order 2\nembedded_order 1\n0 0 0\n1 1/2 1/2\nb 1/2 1/2\nbhat 1 0\n");
  write("overclaimed_pair.tableau", "order 2\nembedded_order 2\n0 0 0\n1 1/2 1/2\nb 1/2 1/2\nbhat 1 0\n");
}

std::string joined(const std::vector<std::string>& args) {
  std::string s;
  for (const std::string& a : args) s += (s.empty() ? "" : " ") + a;
  return s;
}

/// Runs each case in a fresh scratch folder with --out pointing inside the program's (empty) working folder,
/// unless the case gives its own --out.
void expect_refused(const std::string& program, const std::vector<BadInput>& cases) {
  for (const BadInput& c : cases) {
    const ProgramFolder folder;
    write_tableau_files(folder.scratch());
    std::vector<std::string> args;
    if (std::find(c.args.begin(), c.args.end(), "--out") == c.args.end())
      args = {"--out", (folder.cwd() / "out").string()};
    for (std::string a : c.args) {
      if (a.rfind("@S", 0) == 0) a = folder.scratch().string() + a.substr(2);
      args.push_back(a);
    }
    // 20 s is a guard against a hang, not a timing check: a refused grid returns in milliseconds, while one that
    // was allocated (1e10 particles) would fail with bad_alloc or be stopped here, status != 2 either way.
    const ProgramRun run = folder.run(program, args, 20);
    CAPTURE(program);
    const std::string command = joined(c.args);
    CAPTURE(command);
    CAPTURE(run.err);
    CHECK(run.status == 2);
    CHECK(run.out.empty());
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    CHECK(run.err.rfind(program + ": ", 0) == 0);
    for (const std::string& e : c.expect) {
      CAPTURE(e);
      CHECK(run.err.find(e) != std::string::npos);
    }
    CHECK(entry_count(folder.cwd()) == 0);  // nothing written: no out folder, no default ./<program> folder
    CHECK(fs::is_regular_file(folder.scratch() / "a_file"));
  }
}

/// Bad values of the flags every simulating program shares (docs/model.md).
std::vector<BadInput> shared_flag_cases() {
  return {
      {{"--bogus"}, {"unknown flag '--bogus'", "--help"}},
      {{"stray"}, {"unknown flag 'stray'"}},
      {{"--K"}, {"--K: missing value", "> 0"}},
      {{"--K", "--dt", "0.01"}, {"--K: missing value", "> 0"}},
      {{"--grid"}, {"--grid: missing value", "MxN"}},
      {{"--K", "abc"}, {"--K", "expected a number", "'abc'"}},
      {{"--dt", "0.01s"}, {"--dt", "expected a number"}},
      {{"--v0", "fast"}, {"--v0", "expected a number"}},
      {{"--K", " 50"}, {"--K", "expected a number"}},
      {{"--K", "1e999"}, {"--K", "'1e999' is too large to represent"}},
      {{"--K", "nan"}, {"--K", "finite"}},
      {{"--damping", "NaN"}, {"--damping", "finite"}},
      {{"--spacing", "inf"}, {"--spacing", "finite"}},
      {{"--dt", "-inf"}, {"--dt", "finite"}},
      {{"--v0", "inf"}, {"--v0", "finite"}},
      {{"--swing", "fast"}, {"--swing", "expected a number"}},
      {{"--swing", "-inf"}, {"--swing", "finite"}},
      {{"--K", "0"}, {"--K", "> 0"}},
      {{"--K", "-50"}, {"--K", "> 0"}},
      {{"--spacing", "0"}, {"--spacing", "> 0"}},
      {{"--spacing", "-0.1"}, {"--spacing", "> 0"}},
      {{"--dt", "0"}, {"--dt", "> 0"}},
      {{"--dt", "-0.01"}, {"--dt", "> 0"}},
      {{"--damping", "-1"}, {"--damping", ">= 0"}},
      {{"--t-end", "0.001"}, {"--t-end", "expected t-end >= dt"}},
      {{"--dt", "0.5", "--t-end", "0.25"}, {"--t-end", "expected t-end >= dt"}},
      {{"--t-end", "0"}, {"--t-end", "> 0"}},
      {{"--dt", "1e-12"}, {"--dt", "1e9 steps"}},
      {{"--grid", "0x5"}, {"--grid", "M, N >= 2", "'0x5'"}},
      {{"--grid", "1x1"}, {"--grid", "M, N >= 2"}},
      {{"--grid", "20x1"}, {"--grid", "M, N >= 2"}},
      {{"--grid", "-3x5"}, {"--grid", "M, N >= 2"}},
      {{"--grid", "20"}, {"--grid", "MxN"}},
      {{"--grid", "axb"}, {"--grid", "MxN"}},
      {{"--grid", "20x20x20"}, {"--grid", "MxN"}},
      {{"--grid", "100000x100000"}, {"--grid", "4000000"}},
      {{"--grid", "99999999999999999999x2"}, {"--grid", "MxN"}},
      {{"--damping-model", "linear"}, {"--damping-model", "'linear'", "projected or report"}},
      {{"--pins", "all"}, {"--pins", "'all'", "corners, corner, edge or none"}},
      {{"--springs", "bending"}, {"--springs", "'bending'", "structural,shear,flexion"}},
      {{"--springs", "structural,,shear"}, {"--springs", "structural,shear,flexion"}},
      {{"--springs", ""}, {"--springs", "structural,shear,flexion"}},
      {{"--frames", "0"}, {"--frames", "1 to 100000"}},
      {{"--frames", "2.5"}, {"--frames", "whole number"}},
      {{"--out", ""}, {"--out", "folder"}},
      {{"--out", "@S/a_file"}, {"--out", "a_file", "writable folder"}},
      {{"--out", "@S/a_file/sub"}, {"--out", "a_file/sub", "writable folder"}},
      {{"--out", "/proc/cloth_test_out"}, {"--out", "/proc/cloth_test_out", "writable folder"}},
  };
}

}  // namespace

TEST_CASE("parse_number takes a whole finite number and nothing else") {
  CHECK(cloth::parse_number("0.01") == doctest::Approx(0.01).epsilon(1e-15));
  CHECK(cloth::parse_number("-20") == doctest::Approx(-20).epsilon(1e-15));
  CHECK(cloth::parse_number("1e3") == doctest::Approx(1000).epsilon(1e-15));
  for (const char* bad : {"", " 1", "1 ", "1x", "x1", "nan", "-nan", "inf", "-Infinity", "1e999", "--1"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(cloth::parse_number(bad), cloth::InputError);
  }
  CHECK(cloth::parse_integer("20") == 20);
  for (const char* bad : {"", "2.5", "20 ", " 20", "1e3", "99999999999999999999"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(cloth::parse_integer(bad), cloth::InputError);
  }
}

TEST_CASE("CommandLine::parse refuses bad chapter flags with the flag's name and accepted values") {
  cloth::CommandLine cli("prog", "test");
  double tol = 0;
  cli.add_value("--newton-tol", "tol", "Newton tolerance, > 0", [&](const std::string& s) {
    tol = cloth::parse_number(s);
    if (!(tol > 0)) throw cloth::InputError("expected a number > 0");
  });
  const auto error_of = [&](std::vector<const char*> argv) {
    argv.insert(argv.begin(), "prog");
    try {
      cli.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const cloth::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(error_of({"--newton-tol", "1e-9"}) == "accepted");
  CHECK(tol == doctest::Approx(1e-9).epsilon(1e-12));
  CHECK(error_of({"--newton-tol"}) == "--newton-tol: missing value: expected --newton-tol tol (Newton tolerance, > 0)");
  CHECK(error_of({"--newton-tol", "--K", "5"}).find("--newton-tol: missing value") == 0);
  CHECK(error_of({"--newton-tol", "-1"}) == "--newton-tol: expected a number > 0");
  // A negative number is a value, not a flag.
  CHECK(error_of({"--v0", "-5"}) == "accepted");
  CHECK(error_of({"--v0", "-.5"}) == "accepted");
}

TEST_CASE("a program's own default for a common flag: used, printed by --help, overridden by the reader") {
  cloth::CommandLine cli("prog", "test");
  cli.use_common({"--K", "--t-end", "--out"});
  CHECK_THROWS_AS(cli.set_default("--dt", "0.5"), std::logic_error);  // a flag the program does not accept
  cli.set_default("--t-end", "1");
  const auto t_end_of = [&](std::vector<const char*> argv) {
    argv.insert(argv.begin(), "prog");
    return cli.parse(static_cast<int>(argv.size()), argv.data()).run.t_end;
  };
  CHECK(t_end_of({}) == 1.0);
  CHECK(t_end_of({"--t-end", "3"}) == 3.0);
  CHECK(cli.usage().find("simulated time [s] (default 1)") != std::string::npos);
  CHECK(cli.usage().find("(default 2)") == std::string::npos);
  cli.set_default("--K", "-4");  // a default the flag refuses is the program's bug, named as such
  const char* argv[] = {"prog"};
  CHECK_THROWS_WITH_AS(cli.parse(1, argv), "--K (prog's default): expected a number > 0, got -4", cloth::InputError);
}

TEST_CASE("a grid too large is refused before anything is allocated") {
  cloth::SceneParams p;
  p.grid.M = 100000;
  p.grid.N = 100000;
  CHECK_THROWS_AS(cloth::validate(p), cloth::InputError);
  CHECK_THROWS_AS(cloth::Scene{p}, cloth::InputError);
  p.grid.M = 1;
  p.grid.N = 5;
  CHECK_THROWS_AS(cloth::Scene{p}, cloth::InputError);
}

TEST_CASE("unknown method and tableau names list what is accepted") {
  cloth::Scene scene(cloth::SceneParams{});
  cloth::ForceField field(scene);
  try {
    (void)cloth::make_stepper("rk5", field);
    FAIL("make_stepper accepted 'rk5'");
  } catch (const cloth::InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("'rk5'") != std::string::npos);
    for (const std::string& name : cloth::method_names()) CHECK(what.find(name) != std::string::npos);
  }
  try {
    (void)cloth::tableau_from_argument("/nonexistent/rk5");
    FAIL("tableau_from_argument accepted a missing file");
  } catch (const cloth::InputError& e) {
    CHECK(std::string(e.what()).find("rk4") != std::string::npos);
  }
}

#ifdef CLOTH_HAVE_CH01_SPRINGS
TEST_CASE("ch01_springs: bad input gives status 2, one line naming the flag, nothing written") {
  // ch01 is an experiment program that takes the scene flags it uses and no run flags: the cases of those flags,
  // and each flag it does not take refused as unknown.
  const std::vector<std::string> unused = {"--damping", "--damping-model", "--v0", "--swing", "--dt", "--t-end",
                                           "--frames"};
  std::vector<BadInput> cases;
  for (const BadInput& c : shared_flag_cases())
    if (std::find(unused.begin(), unused.end(), c.args.front()) == unused.end()) cases.push_back(c);
  for (const std::string& flag : unused) cases.push_back({{flag, "1"}, {"unknown flag '" + flag + "'", "--help"}});
  expect_refused("ch01_springs", cases);
}

TEST_CASE("ch01_springs: good input does write its folder (so the checks above can fail)") {
  const ProgramFolder folder;
  const ProgramRun run = folder.run("ch01_springs", {"--grid", "4x5", "--out", "out"});
  CHECK(run.status == 0);
  CHECK(fs::is_regular_file(folder.cwd() / "out" / "gradient_check.txt"));
  const ProgramRun help = folder.run("ch01_springs", {"--help", "--out", "help_out"});
  CHECK(help.status == 0);
  CHECK(help.out.find("--grid MxN") != std::string::npos);
  CHECK(!fs::exists(folder.cwd() / "help_out"));
}
#endif

#ifdef CLOTH_HAVE_CH02_EXPLICIT_EULER
TEST_CASE("ch02_explicit_euler: bad input gives status 2, one line naming the flag, nothing written") {
  expect_refused("ch02_explicit_euler", shared_flag_cases());
  expect_refused("ch02_explicit_euler",
                 {{{"--method", "rk4"}, {"--method", "'rk4'", "explicit_euler", "symplectic_euler"}}});
}
#endif

#ifdef CLOTH_HAVE_CH03_RUNGE_KUTTA
TEST_CASE("ch03_runge_kutta: bad input gives status 2, one line naming the flag, nothing written") {
  expect_refused("ch03_runge_kutta", shared_flag_cases());
}

TEST_CASE("ch03_runge_kutta: bad tableau names and files are refused, naming the file and what is wrong") {
  expect_refused("ch03_runge_kutta",
                 {
                     {{"--tableau"}, {"--tableau: missing value"}},
                     {{"--tableau", "rk5"}, {"--tableau", "'rk5'", "rk4", "heun"}},
                     {{"--tableau", "@S/missing.tableau"}, {"--tableau", "missing.tableau"}},
                     {{"--tableau", "@S/empty.tableau"}, {"empty.tableau", "empty tableau"}},
                     {{"--tableau", "@S/ragged.tableau"}, {"ragged.tableau:3", "stage row 2 has 2 numbers: expected 3"}},
                     {{"--tableau", "@S/word.tableau"}, {"word.tableau:3", "'one' is not a number"}},
                     {{"--tableau", "@S/implicit.tableau"}, {"implicit.tableau", "a_11 = 1", "implicit"}},
                     {{"--tableau", "@S/inconsistent.tableau"}, {"inconsistent.tableau", "c_2 = 0.5", "row sum of A is 1"}},
                 });
}
#endif

#ifdef CLOTH_HAVE_CH08_ADAPTIVE_STEP
TEST_CASE("ch08_adaptive_step: bad input gives status 2, one line naming the flag, nothing written") {
  // every shared case but those of --dt, which an adaptive program does not take (refused below as unknown), and
  // the t-end >= dt rule, which holds only for fixed steps
  std::vector<BadInput> shared;
  for (const BadInput& c : shared_flag_cases()) {
    const bool about_dt = std::find(c.args.begin(), c.args.end(), "--dt") != c.args.end() ||
                          std::any_of(c.expect.begin(), c.expect.end(),
                                      [](const std::string& e) { return e.find("dt") != std::string::npos; });
    if (!about_dt) shared.push_back(c);
  }
  expect_refused("ch08_adaptive_step", shared);
  expect_refused("ch08_adaptive_step",
                 {
                     {{"--tol", "0"}, {"--tol", "'0' is not a positive number"}},
                     {{"--tol", "-1e-6"}, {"--tol", "not a positive number"}},
                     {{"--tol", "nan"}, {"--tol"}},
                     {{"--tol", "inf"}, {"--tol"}},
                     {{"--rtol", "abc"}, {"--rtol"}},
                     {{"--atol", "0"}, {"--atol", "not a positive number"}},
                     {{"--tol", "1e-6", "--rtol", "1e-6"}, {"--tol", "either --tol or --rtol/--atol"}},
                     {{"--first-step", "0"}, {"--first-step", "not a positive number"}},
                     {{"--controller", "pid"}, {"--controller", "'pid'", "elementary or pi"}},
                     {{"--norm", "l1"}, {"--norm", "'l1'", "rms or max"}},
                     {{"--tableau", "rk4"}, {"--tableau", "'rk4'", "dopri5", "tsit5"}},
                     {{"--tableau", "@S/implicit.tableau"}, {"--tableau", "implicit.tableau", "implicit"}},
                     {{"--quick"}, {"--quick", "only with --experiments"}},
                     {{"--dt", "0.01"}, {"unknown flag '--dt'"}},
                 });
}
#endif

#ifdef CLOTH_HAVE_CH04_IMPLICIT_EULER
TEST_CASE("ch04_implicit_euler: bad input gives status 2, one line naming the flag, nothing written") {
  expect_refused("ch04_implicit_euler", shared_flag_cases());
}

TEST_CASE("ch04_implicit_euler: bad Newton and linear-solver settings are refused") {
  expect_refused("ch04_implicit_euler",
                 {
                     {{"--linear-solver", "qr"}, {"--linear-solver", "'qr'", "ldlt", "ldu", "cg", "lu"}},
                     {{"--linear-solver"}, {"--linear-solver: missing value"}},
                     {{"--newton-tol", "0"}, {"--newton-tol", "expected a number"}},
                     {{"--newton-tol", "nan"}, {"--newton-tol", "finite"}},
                     {{"--newton-max-iter", "0"}, {"--newton-max-iter", "1"}},
                     {{"--newton-max-iter", "2.5"}, {"--newton-max-iter", "whole number"}},
                     {{"--jacobian", "numeric"}, {"--jacobian", "'numeric'", "exact", "symmetric", "definite"}},
                     {{"--linear-solver", "cg", "--jacobian", "symmetric"}, {"--linear-solver cg", "definite"}},
                     {{"--damping", "1", "--linear-solver", "ldlt", "--jacobian", "exact", "--line-search", "residual"},
                      {"--linear-solver ldlt", "lu"}},
                     {{"--line-search", "energy"}, {"--line-search", "'energy'", "potential", "residual"}},
                     {{"--newton", "two"}, {"--newton", "'two'", "full", "modified", "one"}},
                 });
}
#endif

#ifdef CLOTH_HAVE_CH09_IMPLICIT_RUNGE_KUTTA
TEST_CASE("ch09_implicit_runge_kutta: bad input gives status 2, one line naming the flag, nothing written") {
  expect_refused("ch09_implicit_runge_kutta", shared_flag_cases());
}

TEST_CASE("ch09_implicit_runge_kutta: fully implicit tableaus, --tol without a pair, bad Newton settings refused") {
  expect_refused("ch09_implicit_runge_kutta",
                 {
                     {{"--tableau", "gauss2"}, {"--tableau", "'gauss2'", "sdirk2", "trbdf2", "bdf2"}},
                     {{"--tableau", "@S/gauss2.tableau"}, {"--tableau", "gauss2.tableau", "a_12", "fully implicit"}},
                     {{"--tableau", "@S/ragged.tableau"}, {"--tableau", "ragged.tableau:3"}},
                     {{"--tableau", "@S/overclaimed_pair.tableau"},
                      {"--tableau", "overclaimed_pair.tableau", "bhat claim order 2", "order-2 condition"}},
                     {{"--tableau", "sdirk2", "--tol", "1e-3"}, {"--tol", "embedded", "trbdf2"}},
                     {{"--tableau", "bdf2", "--tol", "1e-3"}, {"--tol", "bdf2"}},
                     {{"--tableau", "trbdf2", "--tol", "0"}, {"--tol", "(0, 1)"}},
                     {{"--newton", "quasi"}, {"--newton", "'quasi'", "full", "modified", "one"}},
                     {{"--newton", "one", "--newton-max-iter", "5"}, {"--newton-max-iter", "one iteration"}},
                     {{"--linear-solver", "cg", "--jacobian", "exact"}, {"--linear-solver", "cg", "definite"}},
                     {{"--newton-tol", "2"}, {"--newton-tol", "(0, 1)"}},
                     {{"--report-runs", "--latest-force-guess"}, {"--latest-force-guess", "--report-runs"}},
                 });
}

TEST_CASE("ch09_implicit_runge_kutta: a tableau file with an embedded pair runs under step control") {
  const ProgramFolder folder;
  write_tableau_files(folder.scratch());
  const ProgramRun run =
      folder.run("ch09_implicit_runge_kutta", {"--tableau", (folder.scratch() / "trapezoid_pair.tableau").string(),
                                               "--tol", "1e-3", "--t-end", "0.1", "--out", "run"});
  CAPTURE(run.err);
  REQUIRE(run.status == 0);
  const std::string txt = read_text(folder.cwd() / "run" / "run.txt");
  CHECK(txt.find("tol = 0.001") != std::string::npos);
  CHECK(txt.find("status = ok") != std::string::npos);
}

TEST_CASE("ch09_implicit_runge_kutta: a controlled TR-BDF2 run reports its Newton work and rejected steps") {
  const ProgramFolder folder;
  const ProgramRun run = folder.run("ch09_implicit_runge_kutta", {"--tableau", "trbdf2", "--tol", "1e-4", "--newton",
                                                                  "modified", "--t-end", "0.2", "--out", "run"});
  CAPTURE(run.err);
  REQUIRE(run.status == 0);
  const std::string txt = read_text(folder.cwd() / "run" / "run.txt");
  for (const char* key : {"tableau = trbdf2", "newton = modified", "tol = 0.0001", "rejected_steps = ",
                          "newton_failures = ", "linear_solves = ", "factorizations = ", "status = ok"}) {
    CAPTURE(key);
    CHECK(txt.find(key) != std::string::npos);
  }
}
#endif

#ifdef CLOTH_HAVE_CH10_CLOTH
TEST_CASE("ch10_cloth: bad input gives status 2, one line naming the flag, nothing written") {
  expect_refused("ch10_cloth", shared_flag_cases());
}

TEST_CASE("ch10_cloth: an unknown method lists every registered name, and a method refuses the flags of another") {
  std::vector<std::string> every_name = {"--method", "'rk5'"};
  for (const std::string& name : cloth::method_names()) every_name.push_back(name);
  expect_refused("ch10_cloth",
                 {
                     {{"--method", "rk5"}, every_name},
                     {{"--method", "xpbd", "--newton", "one"}, {"--newton", "xpbd", "no Newton iteration"}},
                     {{"--method", "rk4", "--jacobian", "exact"}, {"--jacobian", "rk4", "no Newton iteration"}},
                     {{"--method", "rk4", "--iterations", "5"}, {"--iterations", "rk4", "local_global", "xpbd"}},
                     {{"--method", "small_steps", "--iterations", "5"}, {"--iterations", "one iteration per substep"}},
                     {{"--method", "local_global", "--substeps", "5"}, {"--substeps", "local_global", "small_steps"}},
                     {{"--method", "xpbd", "--substeps", "0"}, {"--substeps", "1 to 100000"}},
                     {{"--method", "xpbd", "--damping", "1", "--damping-model", "report"},
                      {"--method xpbd", "--damping-model projected"}},
                     {{"--newton", "quasi"}, {"--newton", "'quasi'", "full", "modified", "one"}},
                     {{"--newton", "one", "--newton-max-iter", "5"}, {"--newton-max-iter", "one iteration"}},
                     {{"--linear-solver", "cg", "--jacobian", "exact"}, {"--linear-solver cg", "definite"}},
                     {{"--method", "sdirk2", "--newton-tol", "2"}, {"--newton-tol", "(0, 1)"}},
                 });
}

TEST_CASE("ch10_cloth: every registered method runs by name and writes the standard outputs with its settings") {
  for (const std::string& method : cloth::method_names()) {
    const ProgramFolder folder;
    std::vector<std::string> args = {"--method", method, "--grid", "5x5", "--dt", "0.005", "--t-end", "0.02", "--out", "run"};
    // Held at their rest lengths, the structural springs of a sheet hung by its corners keep it from moving.
    if (cloth::find_method(method).family == cloth::MethodFamily::constrained)
      args.insert(args.end(), {"--pins", "edge", "--v0", "0"});
    const ProgramRun run = folder.run("ch10_cloth", args);
    CAPTURE(method);
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    for (const char* file : {"final.dat", "energy.dat", "frames.dat", "run.txt"})
      CHECK(fs::is_regular_file(folder.cwd() / "run" / file));
    const std::string txt = read_text(folder.cwd() / "run" / "run.txt");
    CHECK(txt.find("method = " + method + "\n") != std::string::npos);
    CHECK(txt.find("largest_strain_frames = ") != std::string::npos);
    CHECK(txt.find("status = ok") != std::string::npos);
  }
  const ProgramFolder folder;
  const ProgramRun run = folder.run("ch10_cloth", {"--method", "xpbd", "--iterations", "3", "--substeps", "4",
                                                   "--grid", "5x5", "--t-end", "0.02", "--out", "run"});
  REQUIRE(run.status == 0);
  const std::string txt = read_text(folder.cwd() / "run" / "run.txt");
  CHECK(txt.find("iterations = 3\nsubsteps = 4\n") != std::string::npos);
  const ProgramRun implicit = folder.run("ch10_cloth", {"--method", "bdf2", "--newton", "one", "--grid", "5x5",
                                                        "--t-end", "0.02", "--out", "implicit"});
  REQUIRE(implicit.status == 0);
  CHECK(read_text(folder.cwd() / "implicit" / "run.txt").find("newton = one\nlinear_solver = ldlt\n") !=
        std::string::npos);
}
#endif

#ifdef CLOTH_HAVE_CH11_CONTACT
TEST_CASE("ch11_contact: bad input gives status 2, one line naming the flag, nothing written") {
  // The scenes' own --dt is 0.5 ms, under which --t-end 0.001 is a run: that case is given --dt 0.01 here.
  std::vector<BadInput> cases = shared_flag_cases();
  for (BadInput& c : cases)
    if (c.args == std::vector<std::string>{"--t-end", "0.001"}) c.args = {"--t-end", "0.001", "--dt", "0.01"};
  expect_refused("ch11_contact", cases);
  expect_refused("ch11_contact",
                 {
                     {{"--scene", "drape"}, {"--scene", "'drape'", "incline", "sphere", "fold"}},
                     {{"--mu-s", "0.1"}, {"--mu-k", "at most --mu-s = 0.1"}},
                     {{"--mu-s", "-1"}, {"--mu-s", ">= 0"}},
                     {{"--thickness", "0"}, {"--thickness", "> 0"}},
                     {{"--incline-angle", "90"}, {"--incline-angle", "[0, 80]"}},
                     {{"--method", "implicit_euler", "--newton", "modified"}, {"--newton modified", "one or full"}},
                     {{"--method", "implicit_euler", "--linear-solver", "ldlt"}, {"--linear-solver", "expected cg"}},
                     {{"--method", "implicit_euler", "--jacobian", "exact"}, {"--jacobian", "expected definite"}},
                     {{"--method", "rk4", "--newton", "full"}, {"--newton", "rk4 has no Newton iteration"}},
                     {{"--method", "implicit_euler", "--newton", "one", "--newton-max-iter", "5"},
                      {"--newton-max-iter", "exactly one iteration"}},
                     {{"--scene", "fold", "--sphere-radius", "0"}, {"--sphere-radius", "> 0"}},
                     {{"--scene", "fold", "--skin", "1.5"}, {"--skin", "(0, 1]"}},
                     {{"--quick"}, {"--quick", "--report-runs"}},
                     {{"--scene", "fold", "--method", "implicit_euler"}, {"--method implicit_euler", "self-collision"}},
                     {{"--report-runs", "--scene", "fold"}, {"--scene", "--quick and --out only"}},
                 });
}

TEST_CASE("ch11_contact: --help gives implicit_euler's Newton default, one iteration, and a run takes it") {
  const ProgramFolder folder;
  const ProgramRun help = folder.run("ch11_contact", {"--help"});
  REQUIRE(help.status == 0);
  const auto at = help.out.find("\n  --newton ");
  REQUIRE(at != std::string::npos);
  const std::string line = help.out.substr(at + 1, help.out.find('\n', at + 1) - at - 1);
  CAPTURE(line);
  CHECK(line.find("full Newton (default but for implicit_euler)") != std::string::npos);
  CHECK(line.find("single linearised step (implicit_euler's default)") != std::string::npos);
#ifdef CLOTH_HAVE_CH10_CLOTH
  // A program without an exception keeps the plain default.
  const ProgramRun cloth_help = folder.run("ch10_cloth", {"--help"});
  CHECK(cloth_help.out.find("full Newton (default), modified") != std::string::npos);
#endif
  // Without --newton: one iteration per step, also with --linear-solver cg (the only solver it takes), and full
  // Newton when a tolerance asks for more.
  const auto newton_of = [&](const std::vector<std::string>& flags, const std::string& out) {
    std::vector<std::string> args = {"--method", "implicit_euler", "--t-end", "0.02", "--out", out};
    args.insert(args.end(), flags.begin(), flags.end());
    const ProgramRun run = folder.run("ch11_contact", args);
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string txt = read_text(folder.cwd() / out / "run.txt");
    const auto key = txt.find("\nnewton = ");
    REQUIRE(key != std::string::npos);
    return txt.substr(key + 10, txt.find('\n', key + 1) - key - 10);
  };
  CHECK(newton_of({}, "plain") == "one");
  CHECK(newton_of({"--linear-solver", "cg"}, "cg") == "one");
  CHECK(newton_of({"--jacobian", "definite"}, "definite") == "one");
  CHECK(newton_of({"--newton-tol", "1e-6"}, "tol") == "full");
}

TEST_CASE("ch11_contact: run.txt records the geometry of each scene, and the frames stay out of the obstacles") {
  const ProgramFolder folder;
  const ProgramRun incline = folder.run("ch11_contact", {"--t-end", "0.05", "--incline-angle", "20", "--out", "incline"});
  CAPTURE(incline.err);
  REQUIRE(incline.status == 0);
  const std::string txt = read_text(folder.cwd() / "incline" / "run.txt");
  for (const char* key : {"incline_angle = 20\n", "mu_s = 0.3\n", "mu_k = 0.2\n", "thickness = 0.005\n",
                          "contact = after_step\n", "grid = 10x10\n", "status = ok"}) {
    CAPTURE(key);
    CHECK(txt.find(key) != std::string::npos);
  }
  for (const char* method : {"implicit_euler", "small_steps"}) {
    const ProgramRun sphere = folder.run("ch11_contact", {"--scene", "sphere", "--method", method, "--grid", "6x6",
                                                          "--spacing", "0.1", "--t-end", "0.3", "--out", method});
    CAPTURE(sphere.err);
    REQUIRE(sphere.status == 0);
    const std::string s = read_text(folder.cwd() / method / "run.txt");
    CHECK(s.find("ground_z = 0\nsphere = 0.25 0.25 0.3 0.3\n") != std::string::npos);
    CHECK(s.find(std::string("contact = ") +
                 (std::string(method) == "implicit_euler" ? "filtered_cg" : "inequality_constraints")) !=
          std::string::npos);
  }
  const ProgramRun newton = folder.run("ch11_contact", {"--scene", "sphere", "--method", "implicit_euler", "--newton",
                                                        "full", "--grid", "6x6", "--spacing", "0.1", "--dt", "0.005",
                                                        "--t-end", "0.3", "--out", "newton"});
  CAPTURE(newton.err);
  REQUIRE(newton.status == 0);
  CHECK(read_text(folder.cwd() / "newton" / "run.txt").find("newton = full\n") != std::string::npos);
  const ProgramRun fold = folder.run("ch11_contact", {"--scene", "fold", "--grid", "6x20", "--t-end", "0.05", "--out",
                                                      "fold"});
  CAPTURE(fold.err);
  REQUIRE(fold.status == 0);
  const std::string f = read_text(folder.cwd() / "fold" / "run.txt");
  for (const char* key : {"ground_z = 0\n", "thickness = 0.01\n", "self_collision = hash\n",
                          "closest_self_distance_frames = ", "grid = 6x20\n"}) {
    CAPTURE(key);
    CHECK(f.find(key) != std::string::npos);
  }
}
#endif

#ifdef CLOTH_HAVE_CH10_XPBD
TEST_CASE("ch10_xpbd: an experiment program on its own scenes takes --out only") {
  expect_refused("ch10_xpbd", {
                                  {{"--K", "5"}, {"unknown flag '--K'"}},
                                  {{"--method", "xpbd"}, {"unknown flag '--method'"}},
                                  {{"--out"}, {"--out: missing value"}},
                              });
}
#endif

#ifdef CLOTH_HAVE_CH12_BENDING
TEST_CASE("ch12_bending: bad input gives status 2, one line naming the flag, nothing written") {
  // A static single run: the scene flags it uses, no run flags; --grid and --pins only to refuse them.
  const std::vector<std::string> unused = {"--K-flexion", "--damping", "--damping-model", "--springs", "--v0",
                                           "--swing",     "--dt",      "--t-end",         "--frames"};
  std::vector<BadInput> cases;
  for (const BadInput& c : shared_flag_cases())
    if (std::find(unused.begin(), unused.end(), c.args.front()) == unused.end()) cases.push_back(c);
  for (const std::string& flag : unused) cases.push_back({{flag, "1"}, {"unknown flag '" + flag + "'", "--help"}});
  const std::vector<BadInput> own = {
      {{"--bending", "springy"}, {"--bending", "'springy'", "flexion, hinge, quadratic"}},
      {{"--bending-rigidity", "0"}, {"--bending-rigidity", "> 0"}},
      {{"--overhang", "-0.1"}, {"--overhang", "> 0"}},
      {{"--overhang", "0.0501"}, {"--overhang", "whole number of spacings"}},
      {{"--scene", "drape"}, {"--scene", "'drape'", "cantilever"}},
      {{"--full"}, {"--full", "--report-runs"}},
      {{"--grid", "10x10"}, {"--grid", "expected no --grid"}},
      {{"--pins", "edge"}, {"--pins", "expected no --pins"}},
  };
  cases.insert(cases.end(), own.begin(), own.end());
  expect_refused("ch12_bending", cases);
}
#endif
